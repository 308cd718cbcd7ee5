// povml fidelity scene: csg_union_textures
// Rule: a union's texture goes to the members without one; a member with its own keeps it (§16.5).
//       With split_union off the union is kept whole: its members' hits are all kept (§16.2,
//       §16.4). A union with the default split beside it, both moved by the union's transforms.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -6>, rgb 1 }
union {
  sphere { <-0.5, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.1, 0.1> } }
  sphere { <0.3, 0.8, 0.2>, 0.7 }
  box { <-0.2, 0, -0.8>, <0.6, 0.4, 0> }
  pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.6 }
  split_union off
  rotate y*20 translate <-1.3, 0, 0>
}
union {
  sphere { <-0.5, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.1, 0.1> } }
  sphere { <0.3, 0.8, 0.2>, 0.7 }
  pigment { rgb <0.9, 0.8, 0.2> }
  translate <1.5, 0, 0>
}
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
