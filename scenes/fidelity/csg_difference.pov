// povml fidelity scene: csg_difference
// Rule: difference { A B C } is A ∩ ¬B ∩ ¬C (§16.1); the cut surface shows the subtracted
//       object's own texture if it has one, else the difference's (§16.5, pitfall 13). A box minus
//       two spheres, only one of which has a pigment, and its shadow on the floor (§4).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1, 3, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-3, 7, -4>, rgb 1 }
difference {
  box { <-1, 0, -1>, <1, 1.4, 1> }
  sphere { <-1, 1.4, -1>, 0.8 pigment { rgb <0.2, 0.4, 1> } }
  sphere { <0.6, 1.4, -0.4>, 0.6 }
  pigment { rgb <0.9, 0.7, 0.2> } finish { phong 0.5 }
  rotate y*-15
}
plane { y, 0 pigment { rgb <0.8, 0.8, 0.8> } }
