// povml fidelity scene: blob_csg
// Rule: a blob's Inside is field > threshold − 1e-6 (shape/blob.cpp), negated by inverse; as a
//       CSG member it gives every crossing along the ray (IS_CHILD_OBJECT), so intersection and
//       difference keep the parts inside the other members (§16.2, §16.3).
// A box with a blob cut out of it, a blob intersected with a sphere, an inverse blob in an
// intersection.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.3, 0> right x*image_width/image_height }
background { rgb <0.25, 0.3, 0.4> }
light_source { <-4, 8, -6>, rgb 1 }
#declare B = blob { threshold 0.5
  sphere { <-0.5, 0, 0>, 1, 1 }
  sphere { <0.5, 0, 0>, 1, 1 }
  cylinder { <0, -1, 0>, <0, 1, 0>, 0.35, 1 } }
difference {
  box { <-1, -0.5, -0.8>, <1, 0.5, 0.8> }
  object { B translate z*-0.5 }
  pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.5 }
  rotate y*20 translate <-2.1, 0.5, 0> }
intersection {
  object { B }
  sphere { <0.3, 0.3, -0.3>, 0.9 }
  pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.5 }
  translate <0.2, 0.6, 0> }
intersection {
  box { <-0.7, -0.7, -0.7>, <0.7, 0.7, 0.7> }
  object { B scale 0.8 inverse }
  pigment { rgb <0.4, 0.5, 0.95> } finish { phong 0.5 }
  rotate <30, -30, 0> translate <2.3, 0.5, 0> }
plane { y, -0.6 pigment { rgb <0.8, 0.8, 0.75> } }
