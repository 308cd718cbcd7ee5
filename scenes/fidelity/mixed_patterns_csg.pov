// Patterns on the new shapes and on CSG: a checker attached before a torus's transforms (it moves
// with the torus), a gradient on a difference whose cut surface keeps its own brick pigment, a
// hexagon floor under a spotlight, and a merge with a transparent gradient casting a filtered shadow.
// The glass objects stand 0.001 above the floor: a glass cap lying exactly on a plane is a depth tie
// that rounding decides, where povml and POV-Ray can differ.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 6 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> right x*image_width/image_height angle 48 }
light_source { <-4, 10, -5>, rgb 0.8 }
light_source { <3, 8, -2>, rgb 1 spotlight point_at <0, 0, 0> radius 25 falloff 40 tightness 3 }
plane { y, 0 pigment { hexagon rgb <0.9, 0.85, 0.8>, rgb <0.5, 0.55, 0.6>, rgb <0.7, 0.4, 0.3> scale 0.7 rotate y*15 } }
torus { 0.8, 0.3
  pigment { checker rgb <0.9, 0.2, 0.2>, rgb 1 scale 0.25 }
  finish { phong 0.6 }
  rotate <70, 20, 0> scale <1, 1.2, 1> translate <-2.4, 1.1, 0.2>
}
difference {
  cylinder { <0, 0, 0>, <0, 1.8, 0>, 1 }
  box { <-0.4, 0.4, -2>, <0.4, 2.5, 2> pigment { brick rgb 0.6, rgb <0.7, 0.3, 0.2> brick_size <0.4, 0.15, 0.3> mortar 0.03 } }
  pigment { gradient y color_map { [0 rgb <0.2, 0.3, 0.9>] [0.5 rgb <0.9, 0.9, 0.3>] [1 rgb <0.2, 0.3, 0.9>] } scale 1.8 }
  translate <0, 0.001, 0.6>
}
merge {
  sphere { <0, 1, 0>, 0.8 }
  cone { <0, 0, 0>, 0.7, <0, 1, 0>, 0.2 }
  pigment { gradient x color_map { [0 rgbf <1, 0.5, 0.5, 0.9>] [1 rgbt <0.5, 1, 0.5, 0.7>] } scale 1.6 translate -0.8*x }
  interior { ior 1.3 }
  translate <2.4, 0.001, -0.2>
}
