// CSG of cylinders, cones, discs and tori: every hit of each member kept by §16.2's rules, the
// member's own texture on its surface, inverse members in differences, a glass merge of a torus and
// a cylinder (internal surfaces removed), shadows on a plane.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 3.5, -7> look_at <0, 0.6, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6>, rgb 1 }
light_source { <6, 5, -3>, rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } }
difference {
  box { <-1, 0, -1>, <1, 2, 1> }
  cylinder { <0, -1, 0>, <0, 3, 0>, 0.6 pigment { rgb <0.2, 0.4, 0.9> } }
  cylinder { <-2, 1, 0>, <2, 1, 0>, 0.4 }
  pigment { rgb <0.9, 0.5, 0.2> }
  finish { phong 0.5 }
  translate <-2.3, 0, 0.5>
}
intersection {
  cone { <0, 0, 0>, 1.2, <0, 2.2, 0>, 0 }
  torus { 0.7, 0.45 translate y*0.8 pigment { rgb <0.3, 0.8, 0.3> } }
  pigment { rgb <0.8, 0.2, 0.3> }
  translate <0, 0, 0.5>
}
merge {
  torus { 0.8, 0.25 rotate x*90 translate y*1.1 }
  cylinder { <0, 0, 0>, <0, 2.2, 0>, 0.25 }
  disc { <0, 0.01, 0>, y, 1.1, 0.5 }
  pigment { rgbf <0.9, 0.95, 1, 0.85> }
  interior { ior 1.4 }
  finish { reflection 0.05 }
  translate <2.4, 0, 0.3>
}
difference {
  cylinder { <0, 0, 0>, <0, 0.3, 0>, 1.5 open }
  cone { <0, -1, 0>, 1.2, <0, 1, 0>, 0.2 inverse }
  pigment { rgb <0.7, 0.7, 0.2> }
  translate <0, 0, -2.2>
}
