// povml fidelity scene: csg_shadows
// Rule: an intersection and a difference cast the shadows of their kept surfaces only (§4,
//       §16.2): light passes through the hole of the difference. Opaque, so the shadow cache holds
//       the CSG (§4).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -6> look_at <0, 0, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <1, 8, -2>, rgb 1 }
light_source { <-6, 5, 0>, rgb 0.4 }
intersection {
  sphere { <0, 1, 0>, 1 }
  box { <-0.6, 0, -2>, <0.6, 2, 2> }
  pigment { rgb <0.9, 0.3, 0.2> }
  translate <-1.5, 0.3, 0>
}
difference {
  box { <-1, 1, -1>, <1, 1.2, 1> }
  sphere { <0, 1.1, 0>, 0.6 }
  box { <0.3, 0, -0.2>, <2, 2, 0.2> }
  pigment { rgb <0.2, 0.6, 0.9> }
  translate <1.3, 0.4, 0>
}
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
