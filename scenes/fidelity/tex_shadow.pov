// povml fidelity scene: tex_shadow
// Rule: a shadow ray through a layered texture is filtered by every layer's filter and transmit;
//       through a patterned texture by the entries' filters blended (ComputeShadowTexture).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-1.1, 1.2, 0.5>, 0.8 texture { pigment { rgbf <1, 0.3, 0.3, 0.8> } } texture { pigment { checker rgbt <0, 0, 1, 0.5>, rgbt 1 scale 0.3 } } }
box { <0.2, 0.6, -0.5>, <1.6, 1.8, 0.9> texture { gradient y texture_map { [0.3 pigment { rgbt <0, 1, 0, 0.9> }] [0.7 pigment { rgbf <1, 1, 0, 0.7> }] } scale 0.5 } }
