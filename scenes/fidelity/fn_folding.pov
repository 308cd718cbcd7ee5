// POV-Ray's constant folding joins neighbouring constants in a chain: q - 2*3 + 4 is q - 10,
// f(1) / 2 * 4 is f(1) / 8, and x / 3 is x * (1/3)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }

#declare F = function(q) { q - 2*3 + 4 }
#declare G = function { y + 1 }
plane { y, 0 pigment { function { F(x + 10)/ 20 + G(0, 0, 0) / 2 * 4 * 0.1 } color_map { [0 rgb <1,0,0>] [0.5 rgb <0,1,0>] [1 rgb <0,0,1>] } } }
sphere { <0, 1, 0>, 1 pigment { function { z / 3 + pow(x, 3) + pow(y, 5) * 0.1 - 1 - 2 + 3.5 } color_map { [0 rgb 0] [1 rgb 1] } } }
