// A pigment function: its colour's terms read by .red, .green, .gray in another function
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }

#declare P = function { pigment { gradient x color_map { [0 rgb <1, 0, 0.5>] [1 rgb <0, 1, 0.2>] } scale 2 } }
plane { y, 0 pigment { function { P(x, y, z).gray * 0.5 + P(z, x, y).blue } color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { <0, 1, 0>, 1 pigment { function { P(x*3, y, z).red + P(x, y, z).green * 0.3 } color_map { [0 rgb <0,0,1>] [1 rgb <1,1,0>] } } }
