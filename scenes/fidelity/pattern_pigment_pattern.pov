// povml fidelity scene: pattern_pigment_pattern
// Rule: pigment_pattern { PIGMENT } is the greyscale (0.297 r + 0.589 g + 0.114 b, single
//       precision) of the pigment's colour at the point, in a pigment's colour map and a normal
//       (pattern.cpp pigment_pattern); the pigment's own transforms apply after the pattern's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { pigment_pattern { checker rgb 1, rgb <0.2, 0.5, 0.1> scale 0.5 } color_map { [0 rgb <0.1, 0.1, 0.5>] [1 rgb <1, 0.9, 0.6>] } turbulence 0.2 } }
sphere { <-1.1, 1, 0.5>, 1 pigment { pigment_pattern { bozo color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } scale 0.3 } pigment_map { [0 rgb <0.9, 0.1, 0.1>] [0.5 checker rgb 1, rgb 0 scale 0.1] [1 rgb <0.1, 0.9, 0.1>] } } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.6, 0.7, 0.9> } normal { pigment_pattern { gradient y color_map { [0 rgb 0] [1 rgb 1] } scale 0.2 } 0.8 } finish { phong 0.6 } }
