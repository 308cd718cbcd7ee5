// povml fidelity scene: lights_double_illuminate
// Rule: double_illuminate skips the N·L < EPSILON rejection, so a light behind a surface lights it
//       with |N·L| diffuse but gives no highlight; shadows are traced as usual (docs/povray-rules.md §16.6,
//       §3.3). On a union it is set on every member (§16.5).
// The lights are behind two panes (a triangle and a plane-cut wall) seen from the camera's side:
// the double_illuminate ones glow, the plain triangle stays dark.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1.2, 0> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
light_source { <0, 2, 4>, rgb 1 }
light_source { <-3, 5, -6>, rgb 0.2 }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } }
triangle { <-3, 0.2, 1>, <-1.2, 0.2, 1>, <-2.1, 2.6, 1> pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.9 } double_illuminate }
triangle { <-1, 0.2, 1>, <0.8, 0.2, 1>, <-0.1, 2.6, 1> pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.9 } }
union {
  triangle { <1, 0.2, 1>, <2.8, 0.2, 1>, <1.9, 2.6, 1> }
  sphere { <1.9, 0.9, 0.6>, 0.25 }
  pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.8 }
  double_illuminate
}
sphere { <-2.1, 0.6, 2>, 0.4 pigment { rgb <0.9, 0.9, 0.2> } }
