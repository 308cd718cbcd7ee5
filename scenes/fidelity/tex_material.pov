// povml fidelity scene: tex_material
// Rule: material { texture interior }: the material's textures are laid over the object's, its
//       interior is the object's; a declared material; transforms move its textures.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb <0.2, 0.3, 0.6> } }
#declare Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { specular 0.6 reflection 0.1 } } interior { ior 1.5 fade_distance 1 fade_power 2 } }
sphere { <-1.1, 1, 0.5>, 1 material { Glass } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { pigment { rgb <0.9, 0.4, 0.2> } }
      material { texture { pigment { checker rgbt <0, 0, 0, 0.5>, rgbt 1 scale 0.25 } } rotate 20*y } }
sphere { <0.4, 1.7, 1>, 0.4 material { Glass texture { pigment { rgbt <1, 0, 0, 0.7> } } } }
