// povml fidelity scene: blob_graze
// Rule: rays grazing a blob where the field just reaches the threshold: the Bézier hull test
//       skips intervals whose quartic cannot change sign, the solver's double roots near the
//       tangent decide hit or miss (shape/blob.cpp, math/polysolv.cpp); the thin neck of a
//       two-sphere blob whose saddle value barely stays above the threshold, and a pair whose
//       saddle barely falls below it.
// Two necked blobs seen side-on, with a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.3, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
background { rgb <0.1, 0.1, 0.15> }
light_source { <2, 5, -6>, rgb 1 }
blob { threshold 0.5
  sphere { <-0.70, 0, 0>, 1, 1 }
  sphere { <0.70, 0, 0>, 1, 1 }
  translate y*0.7
  pigment { rgb <0.9, 0.9, 0.3> } finish { phong 0.9 phong_size 60 } }
blob { threshold 0.5
  sphere { <-0.709, 0, 0>, 1, 1 }
  sphere { <0.709, 0, 0>, 1, 1 }
  rotate y*30 translate y*-1
  pigment { rgb <0.3, 0.9, 0.9> } finish { phong 0.9 } }
plane { y, -2 pigment { checker rgb 0.2 rgb 0.8 } }
