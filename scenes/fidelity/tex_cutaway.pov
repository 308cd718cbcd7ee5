// povml fidelity scene: tex_cutaway
// Rule: cutaway_textures on an intersection or difference whose members have textures but it has
//       none: a member without a texture shows the textures of the members the point lies in,
//       weighed equally (a difference: its first member's), in shadows too (Determine_Textures).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
difference {
  sphere { <-1.1, 1, 0.5>, 1 texture { pigment { gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] } scale 0.5 } finish { phong 0.5 } } }
  box { <-1.1, 1, -1>, <0.5, 2.5, 0.5> }
  cylinder { <-2.5, 0.6, 0>, <0, 0.6, 0>, 0.3 }
  cutaway_textures
}
intersection {
  box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { pigment { rgbt <0.2, 0.4, 1, 0.4> } } }
  sphere { <1.1, 0.6, 0.2>, 0.85 texture { pigment { checker rgb 1, rgb <0, 0.6, 0> scale 0.2 } } }
  cylinder { <1.1, -1, 0.2>, <1.1, 2, 0.2>, 0.6 inverse }
  cutaway_textures
}
