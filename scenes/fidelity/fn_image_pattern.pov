// Rule: a pattern function (function { pattern { ... } }) makes a function image: directly inside
// 'function W, H { }' of a height_field, and through a declared pattern function in an image_map.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-3> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
#declare P = function { pattern { wood turbulence 0.3 scale 0.2 } }
height_field { function 80, 80 { pattern { bozo scale 0.2 } } translate <-0.5, 0, -0.5> scale <2, 0.4, 2> rotate x*-60 pigment { gradient y color_map { [0 rgb <0.2,0.3,0.8>] [1 rgb <1,0.9,0.6>] } scale <1, 0.4, 1> } }
plane { z, 1 pigment { image_map { function 64, 48 { P(x, y, z) } } scale <4, 3, 1> translate <-2, -1.5, 0> } }
