// povml fidelity scene: superellipsoid_csg
// Rule: a superellipsoid in a CSG pushes every hit it finds (IS_CHILD_OBJECT), not only the
//       first; Inside is its value below 1e-10, negated by inverse; difference and intersection
//       test it against the other members.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
difference {
  superellipsoid { <0.25, 0.25> }
  sphere { <0, 0, -1>, 0.8 }
  translate <-2, 1, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
intersection {
  sphere { 0, 1 }
  superellipsoid { <0.2, 2> scale 1.1 }
  translate <0, 1, 0.5> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
difference {
  box { <-1, -1, -1>, <1, 1, 1> }
  superellipsoid { <2, 0.5> scale 1.15 }
  rotate <0, 30, 0> translate <2.2, 1, 0> pigment { rgb <0.3, 0.5, 0.9> } }
intersection {
  box { <-0.6, 0, -0.6>, <0.6, 0.6, 0.6> }
  superellipsoid { <1, 1> scale 0.5 inverse }
  translate <0, 0, -2.2> pigment { rgb <0.9, 0.8, 0.3> } }
