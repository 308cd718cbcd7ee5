// Pattern functions: the pattern's value with its warps, frequency and wave (Evaluate_TPat)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }

#declare A = function { pattern { agate scale 0.5 } }
#declare M = function { pattern { marble turbulence 0.5 frequency 2 } }
#declare C = function { pattern { checker scale 0.5 } }
plane { y, 0 pigment { function { A(x, y, z) * 0.5 + C(x, y, z) * 0.5 } color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } } }
sphere { <0, 1, 0>, 1 pigment { function { M(x, y, z) } color_map { [0 rgb 0] [1 rgb 1] } } }
