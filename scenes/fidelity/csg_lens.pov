// povml fidelity scene: csg_lens
// Rule: a glass lens as the intersection of two spheres and a merge of two spheres seen through:
//       the shared interior makes the two surfaces one medium (§16.5, §6.2); the merge's inner
//       surfaces are gone (§16.2).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 12 }
camera { location <0, 1, -5> look_at <0, 1, 0> right x*image_width/image_height }
background { rgb <0.2, 0.25, 0.4> }
light_source { <-2, 6, -5>, rgb 1 }
intersection {
  sphere { <0, 0, -1.6>, 2 }
  sphere { <0, 0, 1.6>, 2 }
  pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 phong 0.9 }
  interior { ior 1.5 }
  translate <-1.1, 1, 0>
}
merge {
  sphere { <0, -0.3, 0>, 0.6 }
  sphere { <0, 0.3, 0>, 0.6 }
  pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.7 }
  interior { ior 1.4 }
  translate <1.1, 1, 0>
}
box { <-4, -1, 2>, <-0.01, 4, 2.2> pigment { rgb <0.9, 0.3, 0.3> } }
box { <0.01, -1, 2>, <4, 4, 2.2> pigment { rgb <0.3, 0.3, 0.9> } }
sphere { <0, 1, 1.7>, 0.25 pigment { rgb <1, 1, 0.2> } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.8> } }
