// povml fidelity scene: tex_layers3
// Rule: three layers, declared as one texture: a reflective bottom layer, a filtering middle layer
//       and a patterned top layer; every layer's reflection is traced with its own weight, and the
//       filter of the layers above attenuates the light of those below (ComputeLightedTexture).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
#declare T3 = texture { pigment { rgb <0.2, 0.2, 0.25> } finish { reflection 0.4 phong 0.6 } }
  texture { pigment { rgbf <1, 0.6, 0.3, 0.5> } finish { diffuse 0.3 reflection { 0.1, 0.3 } } }
  texture { pigment { marble turbulence 0.5 color_map { [0 rgbt <0.9, 0.9, 0.9, 0.1>] [0.6 rgbt 1] [1 rgbt 1] } scale 0.7 } }
plane { y, 0 pigment { checker rgb 0.9, rgb <0.3, 0.5, 0.3> } }
sphere { <-1.1, 1, 0.5>, 1 texture { T3 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { T3 rotate 30*y } }
