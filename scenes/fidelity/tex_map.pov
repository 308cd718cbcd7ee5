// povml fidelity scene: tex_map
// Rule: a texture_map: the pattern's value picks the two textures around it, each lit and traced
//       in full (its own finish, reflection and normal), and blends their colours
//       (ComputeOneTextureColour). Entries may be declared textures, layered ones too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
#declare Shiny = texture { pigment { rgb <0.9, 0.8, 0.2> } finish { reflection 0.5 phong 0.8 } }
#declare Rough = texture { pigment { rgb <0.2, 0.4, 0.8> } normal { bumps 0.8 scale 0.05 } }
  texture { pigment { rgbt <1, 1, 1, 0.6> } }
plane { y, 0 texture { gradient x texture_map { [0 Shiny] [0.5 Shiny] [0.5 pigment { rgb 0.8 }] [1 Rough] } } }
sphere { <-1.1, 1, 0.5>, 1 texture { wood turbulence 0.1 texture_map { [0.3 Rough] [0.7 Shiny] } scale 0.3 rotate <20, 30, 0> } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { bozo texture_map { [0.2 pigment { rgb <1, 0, 0> } finish { phong 1 }] [0.8 Shiny] } scale 0.4 } }
