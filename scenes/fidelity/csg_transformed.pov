// povml fidelity scene: csg_transformed
// Rule: a CSG's transforms move every member (§16.1, §14.4): scaled spheres become ellipsoids and
//       rotated boxes get a transform; their hit points are computed in object space and mapped
//       back, and each member's Inside is tested in its own space (§16.2, §16.3). A nested union
//       inside a difference, an intersection of half-spaces (planes), a mesh with an inside vector.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.5, -7> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.25, 0.3, 0.45> }
light_source { <-4, 9, -6>, rgb 1 }
light_source { <5, 4, -3>, rgb 0.3 }
difference {
  sphere { 0, 1 scale <1.3, 0.8, 1> }
  union {
    box { <-0.4, -0.4, -2>, <0.4, 0.4, 2> rotate z*45 }
    sphere { <0, 0.8, -0.6>, 0.45 pigment { rgb <0.9, 0.9, 0.2> } }
  }
  pigment { rgb <0.8, 0.2, 0.3> } finish { phong 0.5 }
  rotate <20, -30, 0>
  scale <1, 1.2, 1>
  translate <-1.8, 1, 0>
}
intersection {
  plane { y, 1.2 }
  plane { -y, 0 }
  plane { x, 0.6 }
  plane { -x, 0.6 }
  plane { z, 0.6 }
  plane { -z, 0.6 }
  sphere { <0, 0.6, 0>, 0.8 inverse }
  pigment { rgb <0.2, 0.6, 0.9> }
  rotate y*35
}
intersection {
  mesh {
    triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
    triangle { <0, 0, 0>, <0, 1, 0>, <0, 0, 1> }
    triangle { <0, 0, 0>, <0, 0, 1>, <1, 0, 0> }
    triangle { <1, 0, 0>, <0, 1, 0>, <0, 0, 1> }
    inside_vector <1, 2, 3>
  }
  sphere { <0.3, 0.3, 0.3>, 0.5 }
  pigment { rgb <0.3, 0.9, 0.4> }
  scale 1.6
  rotate y*-20
  translate <1.5, 0, -0.5>
}
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
