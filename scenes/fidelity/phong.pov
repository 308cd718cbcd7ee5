// povml fidelity scene: phong
// Rule: phong_term = phong * (R.L)^phong_size * lc with R = D - 2(D.N)N, only if R.L > 0 and
//       (phong_size < 60 or R.L > 0.0008); not multiplied by the pigment (docs/povray-rules.md §3.3).
// Left to right: phong 1 with phong_size 3, 40 (default), 300 (the >= 60 cut-off branch).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.08, 0.08, 0.1> }
light_source { <-3, 5, -6>, rgb 1 }
sphere { <-2.2, 0.8, 0>, 0.9 pigment { rgb <0.2, 0.3, 0.7> } finish { phong 1 phong_size 3 } }
sphere { <0, 0.8, 0>, 0.9 pigment { rgb <0.2, 0.3, 0.7> } finish { phong 1 } }
sphere { <2.2, 0.8, 0>, 0.9 pigment { rgb <0.2, 0.3, 0.7> } finish { phong 1 phong_size 300 } }
plane { y, -0.3 pigment { rgb 0.5 } finish { phong 0.5 phong_size 10 } }
