// povml fidelity scene: csg_coincident
// Rule: surfaces exactly on another member's boundary are kept or dropped by that member's Inside
//       (Box::Inside closed, Sphere::Inside strict, §16.2, §16.3), and of equal depths the hit
//       pushed last wins (member hits reversed by intersections and merges). Members are coloured
//       apart so the winner shows: a difference and an intersection of boxes sharing faces, a
//       merge of two boxes sharing a face, a kept union of two coincident boxes, and a merge of
//       two touching spheres.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.3, 4, -7> look_at <0, 0.5, 0> right x*image_width/image_height }
background { rgb <0.25, 0.3, 0.45> }
light_source { <-3, 8, -5>, rgb 1 }
light_source { <4, 3, -6>, rgb 0.4 }
difference {
  box { <-1, 0, -0.6>, <1, 1, 0.6> pigment { rgb <0.9, 0.2, 0.2> } }
  box { <0, 0, -0.6>, <2, 1, 0.6> pigment { rgb <0.2, 0.9, 0.2> } }
  translate <-2, 0, 1>
}
intersection {
  box { <-1, 0, -0.6>, <1, 1, 0.6> pigment { rgb <0.9, 0.2, 0.2> } }
  box { <0, 0, -0.6>, <2, 1, 0.6> pigment { rgb <0.2, 0.9, 0.2> } }
  translate <1.2, 0, 1>
}
merge {
  box { <-0.8, 0, -0.5>, <0, 0.8, 0.5> pigment { rgbt <0.9, 0.9, 0.2, 0.5> } }
  box { <0, 0, -0.5>, <0.8, 0.8, 0.5> pigment { rgbt <0.2, 0.9, 0.9, 0.5> } }
  translate <-2.2, 0, -1.2>
}
union {
  box { <-0.6, 0, -0.5>, <0.6, 0.7, 0.5> pigment { rgb <0.9, 0.5, 0.1> } }
  box { <-0.6, 0, -0.5>, <0.6, 0.7, 0.5> pigment { rgb <0.1, 0.5, 0.9> } }
  split_union off
  translate <0, 0, -1.2>
}
merge {
  sphere { <-0.4, 0.4, 0>, 0.4 pigment { rgbt <1, 0.5, 0.5, 0.6> } }
  sphere { <0.4, 0.4, 0>, 0.4 pigment { rgbt <0.5, 0.5, 1, 0.6> } }
  translate <2.2, 0, -1.2>
}
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
