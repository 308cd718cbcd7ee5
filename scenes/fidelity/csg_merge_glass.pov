// povml fidelity scene: csg_merge_glass
// Rule: a merge keeps a member's hit only outside every other member, so the surfaces inside the
//       overlap vanish; the same spheres as a union (split_union off) keep them (§16.2, pitfall
//       14). Transparent members, also in the shadows, where every crossing filters (§4).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-3, 7, -4>, rgb 1 }
merge {
  sphere { <-0.35, 0.8, 0>, 0.7 }
  sphere { <0.35, 0.8, 0>, 0.7 }
  pigment { rgbt <1, 0.6, 0.6, 0.6> } finish { ambient 0.1 diffuse 0.4 }
  translate <-1.4, 0, 0>
}
union {
  sphere { <-0.35, 0.8, 0>, 0.7 }
  sphere { <0.35, 0.8, 0>, 0.7 }
  pigment { rgbt <0.6, 0.6, 1, 0.6> } finish { ambient 0.1 diffuse 0.4 }
  split_union off
  translate <1.4, 0, 0>
}
box { <-3, 0, 1.5>, <3, 2, 1.7> pigment { rgb <0.9, 0.9, 0.3> } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.8> } }
