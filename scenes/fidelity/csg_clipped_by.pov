// povml fidelity scene: csg_clipped_by
// Rule: clipped_by keeps an object's hits inside every clip object (Point_In_Clip), which leaves
//       an open shell; the clipped object's Inside asks the clip objects too (§15.8, §16.2). Clip
//       objects are never seen and move with the object's later transforms. A union with
//       clipped_by is kept whole (§16.4): its no_shadow member casts a shadow. A clipped glass
//       sphere (the ray inside the shell toggles the interior list), a clipped difference, an
//       inverted clip object, shadows through all of them.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 3, -6.5> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.25, 0.3, 0.45> }
light_source { <-3, 8, -5>, rgb 1 }
sphere { <0, 0.8, 0>, 0.8
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 }
  clipped_by { plane { y, 1 } }
  translate <-2.2, 0, 0>
}
sphere { <0, 0.8, 0>, 0.8
  clipped_by { box { <-1, 0, -0.4>, <1, 2, 1> } }
  clipped_by { sphere { <0, 1.4, -0.5>, 0.6 inverse } }
  pigment { rgb <0.2, 0.7, 0.9> }
  rotate y*20 translate <-0.6, 0, 0>
}
sphere { <0, 0.7, 0>, 0.7
  pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { ambient 0 diffuse 0.1 phong 0.8 }
  interior { ior 1.4 }
  clipped_by { plane { -z, 0.3 } }
  translate <0.9, 0, -0.3>
}
difference {
  box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> }
  sphere { <0, 1, -0.5>, 0.5 }
  clipped_by { sphere { <0, 0.5, 0>, 0.65 } }
  pigment { rgb <0.9, 0.8, 0.2> }
  rotate y*30 translate <2.3, 0, 0.3>
}
union {
  sphere { <0, 0.3, 0>, 0.3 pigment { rgb <0.8, 0.2, 0.8> } no_shadow }
  sphere { <0.5, 0.3, 0>, 0.25 }
  clipped_by { box { -10, 10 } }
  pigment { rgb <0.3, 0.9, 0.4> }
  translate <-0.9, 0, -1.6>
}
box { <-4, 0, 2>, <4, 3, 2.2> pigment { rgb <0.9, 0.9, 0.9> } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
