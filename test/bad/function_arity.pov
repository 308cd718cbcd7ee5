#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
#declare F = function(a, b) { a + b }
sphere { 0, 1 pigment { function { F(x) } } }
