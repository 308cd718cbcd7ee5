// The function pattern in a pigment: a user function of two parameters called from the body
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }

#declare F = function(a, b) { sin(a*3) * cos(b*2) * 0.5 + 0.5 }
plane { y, 0 pigment { function { F(x, z) + x*x*0.1 } color_map { [0 rgb <1,0,0>] [0.5 rgb <0,1,0>] [1 rgb <0,0,1>] } } }
sphere { <0, 1, 0>, 1 pigment { function { abs(x) + select(y - 1, 0.2, 0.7) } color_map { [0 rgb 0] [1 rgb 1] } } }
