// povml fidelity scene: blob_textures_inside
// Rule: a blob whose components carry textures is shaded by their blend on both sides of its
//       surface: Determine_Textures has no interior texture, so interior_texture is not seen
//       from inside (trace.cpp: the multi-textured path replaces the Interior_Texture test).
// A transparent two-sphere blob, one component textured, with a red interior_texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at 0 right x*image_width/image_height }
light_source { <-4, 6, -5>, rgb 1 }
background { rgb <0.2,0.3,0.4> }
blob { threshold 0.5
  sphere { <-0.6, 0, 0>, 1.2, 1 pigment { rgbf <1, 1, 0.5, 0.7> } }
  sphere { <0.6, 0, 0>, 1.2, 1 }
  texture { pigment { rgbf <0.5, 1, 1, 0.6> } }
  interior_texture { pigment { rgb <1, 0, 0> } } }
