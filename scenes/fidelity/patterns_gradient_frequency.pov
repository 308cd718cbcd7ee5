// povml fidelity scene: patterns_gradient_frequency
// Rule: gradient's vector is normalised; frequency and phase wrap the value by
//       fmod(v·frequency + phase, 1.00001) (docs/povray-rules.md §17.1, §17.5); waves shape it.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -6> look_at <0, 0, 0> right x*image_width/image_height }
light_source { <3, 10, -4> color rgb 1 }
#declare M = color_map { [0 rgb <0.9, 0.1, 0.1>] [0.5 rgb <0.1, 0.8, 0.2>] [1 rgb <0.1, 0.2, 0.9>] }
plane { y, 0 pigment { gradient <2, 0, 1> color_map { M } frequency 3 phase 0.25 scale 4 } }
sphere { <-2, 1, 0>, 1 pigment { gradient x color_map { M } frequency 2 phase 0.1 triangle_wave } }
sphere { <0, 1, 0.5>, 1 pigment { gradient y color_map { M } sine_wave frequency 1.5 } }
sphere { <2, 1, 0>, 1 pigment { gradient z color_map { M } cubic_wave phase 0.3 scale 0.7 } }
sphere { <0, 0.5, -2.5>, 0.5 pigment { gradient x color_map { M } scallop_wave frequency 2 } }
sphere { <1.5, 0.5, -2.5>, 0.5 pigment { gradient y color_map { M } poly_wave 2.5 } }
