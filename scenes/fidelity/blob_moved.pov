// povml fidelity scene: blob_moved
// Rule: component transforms (shape/blob.cpp Translate/Rotate/Scale_Blob_Element): a sphere
//       component moves its centre and scales uniformly in place, a non-uniform scale or a
//       matrix turns it into an ellipsoid with a transform of its own; a cylinder always has one.
//       Object transforms compose into the blob's Trans (the ray is brought into blob space with
//       its direction renormalised, depths scaled back); its box is Compute_BBox's, mapped.
// Two blobs: one with moved components, one rotated and non-uniformly scaled as a whole.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.4, 0> right x*image_width/image_height }
background { rgb <0.3, 0.3, 0.4> }
light_source { <-5, 7, -5>, rgb 1 }
light_source { <5, 3, -6>, rgb 0.3 }
blob { threshold 0.5
  sphere { <0, 0, 0>, 1, 1.5 scale <1.6, 0.6, 1> rotate z*30 translate <-2, 0.8, 0> }
  sphere { <0, 0, 0>, 0.5, 1 scale 2 translate <-1.2, 0.5, 0> }
  sphere { <0.3, 0, 0>, 0.9, 1 rotate y*40 translate <-2.2, 0.2, -0.5> }
  cylinder { <0, 0, 0>, <1, 0, 0>, 0.4, 1.2 rotate z*70 scale <1, 1.5, 1> translate <-2.6, -0.2, 0.3> }
  pigment { rgb <0.9, 0.6, 0.2> } finish { phong 0.7 } }
blob { threshold 0.6
  sphere { <-0.6, 0, 0>, 1, 1 }
  sphere { <0.6, 0, 0>, 1, 1 }
  cylinder { <0, 0, -0.8>, <0, 0, 0.8>, 0.45, 1 }
  scale <1.2, 0.7, 1> rotate <20, 30, 10> translate <1.5, 0.7, 0>
  pigment { rgb <0.3, 0.7, 0.9> } finish { phong 0.7 } }
plane { y, -0.6 pigment { rgb <0.8, 0.8, 0.75> } }
