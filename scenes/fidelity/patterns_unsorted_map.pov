// povml fidelity scene: patterns_unsorted_map
// Rule: map entries are not sorted: [0.8 red][0.2 blue] is red below 0.2 and blue from 0.2 up;
//       a single entry is a constant (docs/povray-rules.md §17.2).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> right x*image_width/image_height }
light_source { <2, 8, -5> color rgb 1 }
plane { y, 0 pigment { gradient x color_map { [0.8 rgb <1, 0, 0>] [0.2 rgb <0, 0, 1>] } scale 1.5 } }
sphere { <-1.2, 1, 0>, 1 pigment { gradient y color_map { [0.6 rgb <0.2, 0.9, 0.2>] [0.3 rgb <0.9, 0.9, 0.1>] [0.9 rgb <0.5, 0.1, 0.6>] } } }
sphere { <1.2, 1, 0>, 1 pigment { gradient y color_map { [0.5 rgb <0.3, 0.6, 0.9>] } } }
