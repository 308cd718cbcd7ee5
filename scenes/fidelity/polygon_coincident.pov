// povml fidelity scene: polygon_coincident
// Rule: a polygon lying in another object's surface ties with it at equal depths, and POV-Ray
//       keeps the first object its bounding tree meets (docs/povray-rules.md §2.1, §15.8): the order in
//       which the ray enters the objects' single-precision boxes. A polygon's box is its points'
//       extent, an axis thinner than 1e-3 widened by 1e-3 on each side (Polygon::Compute_BBox),
//       so a flat polygon's box is entered 1e-3 early. Left: a polygon on a box's top face;
//       right: one on the floor plane, another upright behind a ball.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 3, -4> look_at <0, 0.3, 0> right x*image_width/image_height }
light_source { <-5, 9, -6>, rgb 1 }
box { <-1, -1, -1>, <1, 0.5, 1> pigment { rgb <0.2, 0.9, 0.2> } translate x*-1.1 }
polygon { 5, <-0.8, -0.8>, <0.8, -0.8>, <0.8, 0.8>, <-0.8, 0.8>, <-0.8, -0.8>
  rotate x*90 translate <-1.1, 0.5, 0> pigment { rgb <0.9, 0.2, 0.2> } }
polygon { 5, <-0.8, -0.8>, <0.8, -0.8>, <0.8, 0.8>, <-0.8, 0.8>, <-0.8, -0.8>
  rotate x*90 translate <1.1, -1, 0> pigment { rgb <0.9, 0.2, 0.9> } }
quadric { <1, 1, 1>, <0, 0, 0>, <-2.2, 0, 0>, 1.21 - 0.36 pigment { rgb <0.2, 0.3, 0.9> } }
polygon { 5, <-0.8, -0.8>, <0.8, -0.8>, <0.8, 0.8>, <-0.8, 0.8>, <-0.8, -0.8>
  translate <1.1, 0, 0> pigment { rgb <0.9, 0.9, 0.2> } }
plane { y, -1 pigment { rgb 0.7 } }
