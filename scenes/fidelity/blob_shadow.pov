// povml fidelity scene: blob_shadow
// Rule: shadow rays test a blob like any ray (shape/blob.cpp, DEPTH_TOLERANCE 1e-2 in blob
//       space units of the ray), so blobs shadow the floor and themselves; hierarchy off sums
//       the elements in their own order instead of the bounding sphere tree's; sturm solves
//       every interval's quartic with Sturm sequences.
// Two blobs on a floor lit by two lights: one with hierarchy off, one with sturm.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 3.5, -6.5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
light_source { <5, 4, -6>, rgb 0.35 }
blob { threshold 0.5
  sphere { <-1.6, 1.0, 0>, 0.9, 1 }
  sphere { <-0.9, 0.5, 0.2>, 0.8, 1 }
  sphere { <-1.3, 1.6, 0.3>, 0.6, 1 }
  cylinder { <-2.2, 0.3, -0.4>, <-0.6, 1.5, 0.3>, 0.3, 1 }
  hierarchy off
  pigment { rgb <0.9, 0.5, 0.1> } finish { phong 0.6 } }
blob { threshold 0.6
  sphere { <1, 0.7, 0>, 0.9, 1.2 }
  sphere { <1.8, 0.6, -0.3>, 0.8, 1.2 }
  cylinder { <0.6, 0.2, 0.8>, <2.2, 1.4, 0.5>, 0.35, 1 }
  sturm
  pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.5 roughness 0.02 } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
