// povml fidelity scene: patterns_plain_then_pattern
// Rule: a plain-colour pigment keeps the transforms it received (its own, its texture's, its
//       object's); a later edit that gives it a pattern keeps them (docs/povray-rules.md §17.9, §14.7).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 1, 0> right x*image_width/image_height }
light_source { <2, 8, -3> color rgb 1 }
// the texture is made by the finish, scaled with the sphere, then given a pattern
sphere { <-2.2, 0.5, 0>, 0.5 finish { phong 0.5 } scale 2 pigment { checker rgb 1, rgb 0 } }
// a declared plain pigment with its own scale, edited into a checker
#declare P = pigment { rgb <1, 0.5, 0> scale 0.5 }
sphere { <0, 1, 0>, 1 pigment { P checker rgb <1, 0.5, 0>, rgb <0, 0.3, 0.8> } }
// a texture block's rotate on a plain pigment, then a gradient
#declare S = sphere { <0, 0, 0>, 1 texture { pigment { rgb 1 } rotate z*45 } translate <2.2, 1, 0> }
object { S pigment { gradient x color_map { [0 rgb <0.9, 0.1, 0.1>] [1 rgb <0.1, 0.9, 0.2>] } } }
plane { y, 0 pigment { rgb 0.8 } translate y*0.01 pigment { checker rgb 0.8, rgb 0.5 } }
