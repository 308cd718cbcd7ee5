// povml fidelity scene: julia_union_row
// Rule: a julia fractal is shaded at the point its march found, with the normal computed there
//       on the iteration stack as the march left it (a function map's may differ from a fresh
//       Iteration's); in a union kept whole (split_union off) every member's crossings are
//       collected before the nearest is picked: 20 fractals in a row, each crossed several
//       times, and the nearest crossing keeps its own point and normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 0.4, -4> look_at <0, 0, 0> angle 60 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
union {
  #for (i, 0, 19)
    julia_fractal { <0.5, 0.2, 0.1, 0.0> hypercomplex sin max_iteration 4 precision 10 translate <0.01*i, 0.01*i, 0.6*i> }
  #end
  split_union off
  pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.5 }
}
