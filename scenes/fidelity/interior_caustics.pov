// povml fidelity scene: interior_caustics
// Rule: interior { caustics C } fakes caustics in shadows: a shadow ray crossing the surface is let
//       through 1 + |N·L|^(45·C) times more, N the layer's normal there, bumps included
//       (ComputeShadowTexture); finish { caustics C } is the legacy form, copied as written.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <-1.1, 1, 0.5>, 1 pigment { rgbf <0.9, 0.9, 1, 0.9> } finish { specular 0.5 } interior { ior 1.5 caustics 0.8 } }
box { <0.4, 0.3, -0.5>, <1.8, 1.2, 0.9> texture { pigment { rgbt <1, 0.6, 0.3, 0.7> } normal { bumps 0.6 scale 0.2 } }
      texture { pigment { rgbt 0.9 } } interior { ior 1.2 caustics 0.3 } }
sphere { <0.4, 1.8, 1.5>, 0.4 pigment { rgbf <1, 1, 0.5, 0.8> } finish { caustics 1 } }
