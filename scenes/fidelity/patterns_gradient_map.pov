// povml fidelity scene: patterns_gradient_map
// Rule: map entries are searched in the order written; two entries with the same value make a
//       sharp step; below the first value the first colour, above the last the last
//       (docs/povray-rules.md §17.2, §17.3); the pattern is scaled inside the pigment (§17.1).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> right x*image_width/image_height }
light_source { <4, 9, -5> color rgb 1 }
plane { y, 0
  pigment { gradient x
    colour_map { [0.1 color rgb <1, 0.2, 0>] [0.3, color rgb <0.2, 0.9, 0.1>] [0.3 rgb <0, 0.1, 1>]
                 [0.7 rgb <1, 1, 0.2>] [0.9 color red 0.4 green 0.1] }
    scale 2.5 }
}
sphere { <0, 1, 0>, 1
  pigment { gradient y color_map { [0.0 0.5 color rgb <0.1, 0.3, 0.9> color rgb 1] [0.5 1 color rgb 1 color rgb <0.9, 0.2, 0.1>] } scale 2 translate -y }
  finish { phong 0.5 } }
