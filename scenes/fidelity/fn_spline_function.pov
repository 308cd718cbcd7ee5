// A spline function: the terms of a cubic spline at the function's parameter
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }

#declare S = spline { cubic_spline -1, <0, 0, 0> 0, <1, 0.2, 0.5> 1, <0.3, 1, 0> 2, <0, 0.5, 1> 3, <1, 1, 1> }
#declare F = function { spline { S } }
plane { y, 0 pigment { function { F(x).x * 0.5 + F(z).y * 0.5 } color_map { [0 rgb <1,0,0>] [1 rgb <0,1,0>] } } }
sphere { <0, 1, 0>, 1 pigment { function { F(y * 2).z } color_map { [0 rgb 0] [1 rgb 1] } } }
