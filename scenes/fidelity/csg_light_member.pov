// povml fidelity scene: csg_light_member
// Rule: a light_source written inside a CSG is a global light moved by the CSG's transforms; it
//       has no geometry, so it neither clips an intersection nor counts in its Inside tests (§19.1).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*image_width/image_height }
background { rgb <0.2, 0.25, 0.35> }
intersection {
  box { <-1, 0, -1>, <1, 1.5, 1> }
  light_source { <-2, 5, -3>, rgb 1 }
  sphere { <0, 0.75, 0>, 1.2 }
  pigment { rgb <0.9, 0.5, 0.2> }
  rotate y*25
  translate <0.5, 0, 0>
}
merge {
  light_source { <3, 2, -4>, rgb <0.3, 0.3, 0.5> }
  sphere { <-2.2, 0.5, 0.5>, 0.5 }
  sphere { <-2.2, 1.1, 0.5>, 0.35 }
  pigment { rgb <0.3, 0.8, 0.4> }
}
plane { y, 0 pigment { rgb <0.8, 0.8, 0.8> } }
