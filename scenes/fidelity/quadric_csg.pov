// povml fidelity scene: quadric_csg
// Rule: a quadric's Inside is its left side ≤ 0, the surface included (Quadric::Inside), and
//       inverse negates every coefficient (Quadric::Invert), so an inverted quadric holds its
//       surface too (docs/povray-rules.md §16.2, §16.3). Intersections, differences (the later members
//       inverted) and a merge keep each member's hits by those tests; clipped_by keeps the hits
//       inside the clip (§15.8). Every quadric here is unbounded alone, bounded by its CSG.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 3.5, -7> look_at <0, 0.7, 0> right x*image_width/image_height angle 55 }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-5, 9, -6>, rgb 1 }
light_source { <6, 5, -3>, rgb 0.4 }
#declare Ball = quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
// a box with a vertical hole (x² + z² ≤ 0.16 taken away) and a horizontal one
difference {
  box { <-0.8, 0, -0.8>, <0.8, 1.4, 0.8> }
  quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.16 pigment { rgb <0.2, 0.4, 0.9> } }
  quadric { <0, 1, 1>, <0, 0, 0>, <0, -1.4, 0>, 0.49 - 0.09 }
  pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.5 }
  translate <-2.6, 0, 0.6> }
// a ball cut by a cylinder along x: a bead
intersection {
  object { Ball }
  quadric { <0, 1, 1>, <0, 0, 0>, <0, 0, 0>, -0.36 pigment { rgb <0.9, 0.9, 0.3> } }
  pigment { rgb <0.3, 0.8, 0.4> }
  scale 0.8 translate <-0.8, 0.8, 0> }
// a ball without its lower half (the plane y = 0 as a quadric half-space, taken away)
difference {
  object { Ball }
  quadric { <0, 0, 0>, <0, 0, 0>, <0, 1, 0>, 0 }
  pigment { rgb <0.8, 0.3, 0.6> } finish { phong 0.4 }
  scale 0.7 rotate x*-30 translate <0.9, 0.7, -0.6> }
// a cone y² ≥ x² + z² inside a box, with a ball hollowed out by inverse
intersection {
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, 0 }
  box { <-2, 0.01, -2>, <2, 1.5, 2> }
  object { Ball scale 0.55 translate y*1.2 inverse pigment { rgb <0.9, 0.2, 0.2> } }
  pigment { rgb <0.4, 0.7, 0.9> }
  translate <2.4, 0, 0.8> }
// two glass ellipsoids merged: their inner surfaces are gone
merge {
  quadric { <4, 16, 4>, <0, 0, 0>, <0, 0, 0>, -1 }
  quadric { <16, 4, 4>, <0, 0, 0>, <0, 0, 0>, -1 }
  pigment { rgbf <0.9, 0.95, 1, 0.8> } finish { ambient 0 diffuse 0.1 phong 0.6 } interior { ior 1.4 }
  translate <0.4, 0.5, -2> }
// a hyperboloid of one sheet clipped by a box
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.04
  clipped_by { box { <-1, -0.6, -1>, <1, 0.6, 1> } }
  pigment { rgb <0.95, 0.8, 0.4> }
  translate <-1.8, 0.6, -1.8> }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
