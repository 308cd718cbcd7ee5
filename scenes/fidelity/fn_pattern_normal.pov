// The function pattern in a normal: the slope of the function's value
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }

plane { y, 0 pigment { rgb 0.8 } normal { function { abs(sin(x*4)*cos(z*4)) } 1.5 } }
sphere { <0, 1, 0>, 1 pigment { rgb 1 } normal { function { mod(abs(x*5), 1) - y/3 } 0.8 } finish { phong 0.5 } }
