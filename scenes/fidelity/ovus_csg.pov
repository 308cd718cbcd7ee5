// povml fidelity scene: ovus_csg
// Rule: Ovus::Inside is within either sphere or within the joint between its heights (surface
//       excluded), negated by inverse; in a CSG every hit is pushed with its part, and the
//       other members cut it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
difference {
  ovus { 1, 0.7 }
  box { <-2, -2, -2>, <2, 2, -0.3> }
  translate <-2.2, 1, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
intersection {
  ovus { 0.6, 1.1 }
  box { <-0.4, -1, -1>, <0.4, 2, 1> }
  translate <0, 0.6, 0.3> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
difference {
  sphere { <0, 0.8, 0>, 1 }
  ovus { 0.7, 0.9 scale 1.1 }
  translate <2.3, 0.7, 0> pigment { rgb <0.3, 0.5, 0.9> } }
intersection {
  box { <-0.6, 0, -0.6>, <0.6, 1, 0.6> }
  ovus { 0.4, 0.3 translate 0.4*y inverse }
  translate <0, 0, -2.2> pigment { rgb <0.9, 0.8, 0.3> } }
