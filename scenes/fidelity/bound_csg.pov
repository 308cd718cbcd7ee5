// bounded_by on top-level CSG: the bound is kept; a ray meets the CSG only if it meets the
// bounding object or starts inside it, and a smaller bound box is the CSG's box
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <4, 6, -5> rgb 1 }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.8 } }
union {
  sphere { <-2, 0.5, 0>, 0.8 } sphere { <-2, 1.4, 0>, 0.5 }
  pigment { rgb <1, 0.3, 0.2> }
  bounded_by { sphere { <-2, 0.9, -0.5>, 0.9 } }
}
intersection {
  box { <-0.8, -0.5, -0.8>, <0.8, 1.5, 0.8> } sphere { <0, 0.5, 0>, 1.1 }
  pigment { rgb <0.2, 1, 0.4> }
  bounded_by { box { <-2, 0, -2>, <2, 1, 2> } }
}
merge {
  cylinder { <2, -0.5, 0>, <2, 1.5, 0>, 0.5 } sphere { <2, 1.5, 0>, 0.7 }
  pigment { rgb <0.3, 0.4, 1> filter 0.5 }
  bounded_by { box { <1, -1, -3>, <3, 3, 3> } }
}
