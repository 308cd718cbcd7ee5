// povml fidelity scene: blob_textures
// Rule: a blob whose components carry textures is shaded by their blend (Blob::Determine_Textures,
//       trace.cpp ComputeTextureColour): every element whose field is not 0 at the hit counts,
//       weighed by the field's magnitude, the weights scaled to sum to 1; a component without a
//       texture stands for the blob's own texture; a cylinder's hemispheres carry its texture;
//       component textures move with the component's later transforms and the blob's. Shadows
//       through a blob with a transparent component are filtered by the same blend.
// Two blended blobs on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6.5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 8, -5>, rgb 1 }
blob { threshold 0.5
  sphere { <-1.9, 0.8, 0>, 0.9, 1 pigment { rgb <1, 0.2, 0.1> } }
  sphere { <-1.1, 0.8, 0>, 0.9, 1 texture { pigment { checker rgb <0.1, 0.3, 1> rgb 1 scale 0.2 } finish { phong 0.8 } } translate y*0.3 }
  sphere { <-1.5, 1.5, -0.2>, 0.7, 1 }
  cylinder { <-2.3, 0.2, -0.5>, <-0.7, 0.3, -0.5>, 0.35, 1 pigment { rgb <0.2, 1, 0.2> } finish { specular 0.6 } }
  pigment { rgb <1, 1, 0.3> } finish { phong 0.4 }
  rotate y*15 }
blob { threshold 0.6
  sphere { <0, 0, 0>, 1, 1 pigment { gradient x color_map { [0 rgb <1, 0.4, 0>] [1 rgb <0.4, 0, 1>] } } scale <1.5, 1, 1> translate <1.3, 0.8, 0> }
  sphere { <2.1, 0.9, -0.3>, 0.8, 1 pigment { rgbf <0.6, 1, 0.9, 0.8> } }
  sphere { <1.5, 1.5, 0.4>, 0.8, 1.2 }
  pigment { rgb <0.9, 0.9, 0.9> }
  scale <1, 1.1, 1> rotate y*-20 }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
