// bounded_by inside a CSG is never removed: each member is met only by rays that meet its bound
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-4, 6, -5> rgb 1 }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.8 } }
union {
  sphere { <-1.5, 0.5, 0>, 1 bounded_by { box { <-2.5, 0, -1>, <-1, 1.5, 1> } } pigment { rgb <1, 0.8, 0.2> } }
  torus { 0.8, 0.3 rotate 90*x translate <1.5, 0.5, 0> bounded_by { sphere { <1.8, 0.8, -0.5>, 0.9 } } pigment { rgb <0.2, 0.8, 1> } }
  split_union off
}
difference {
  box { <-0.5, -1, 1>, <0.5, 2, 2> }
  sphere { <0, 0.5, 1>, 0.7 bounded_by { box { <-1, 0, 0>, <1, 2, 2> } } }
  pigment { rgb <0.9, 0.4, 0.9> }
}
