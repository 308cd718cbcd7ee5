#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
#declare F = function(a) { a * 1e200 * 1e200 / (a - a) + ln(0) + sqrt(-1) }
#declare G = function(a) { F(a) - F(a) }
#debug concat(str(F(1), 0, 3), " ", str(G(1), 0, 3), "\n")
sphere { 0, 1 pigment { function { G(x) + F(y) } } }
