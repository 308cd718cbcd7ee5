// povml fidelity scene: csg_split_no_shadow
// Rule: per-object flags are tested on top-level objects: a split union's no_shadow member casts
//       no shadow; with split_union off the same member casts one, since only the union's flag is
//       tested (§16.4, pitfall 11).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <2, 8, -3>, rgb 1 }
union {
  sphere { <0, 1, 0>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } no_shadow }
  sphere { <0, 1, 1>, 0.4 pigment { rgb <0.2, 0.9, 0.2> } }
  translate <-1.3, 0, 0>
}
union {
  sphere { <0, 1, 0>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } no_shadow }
  sphere { <0, 1, 1>, 0.4 pigment { rgb <0.2, 0.9, 0.2> } }
  split_union off
  translate <1.3, 0, 0>
}
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
