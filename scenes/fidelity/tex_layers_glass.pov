// povml fidelity scene: tex_layers_glass
// Rule: the transmitted ray of a layered texture is traced once, filtered by every layer's
//       filter and transmit; the top layer's normal refracts it (ComputeLightedTexture,
//       ComputeRefraction). A glass sphere with a filtering base and a spotted top layer.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb <0.2, 0.3, 0.6> } }
sphere { <-0.6, 1, 0>, 1
  texture { pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { specular 0.6 reflection 0.1 } }
  texture { pigment { spotted color_map { [0.5 rgbt 1] [0.6 rgbf <1, 0.2, 0.2, 0.5>] } scale 0.2 } }
  interior { ior 1.5 } }
sphere { <1.3, 0.6, -0.4>, 0.6
  texture { pigment { rgbt <1, 1, 1, 0.95> } }
  texture { pigment { rgbt <0.2, 0.4, 1, 0.5> } normal { bumps 0.5 scale 0.1 } finish { phong 0.9 } }
  interior { ior 1.3 } }
