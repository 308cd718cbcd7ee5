// povml fidelity scene: polygon_shadow
// Rule: polygons in shadow rays (docs/povray-rules.md §4, §15.7): an opaque polygon with a hole casts a
//       shadow with a hole; a filtered one a coloured shadow; shadow rays from a polygon's own
//       surface skip it by the 1e-3 tolerance (and the polygon's own 1e-8); a polygon shadowed by
//       another. Shadows fall on the floor, a sphere and a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
light_source { <6, 3, 1>, rgb 0.4 }
polygon { 10,
  <-0.8, -0.8>, <0.8, -0.8>, <0.8, 0.8>, <-0.8, 0.8>, <-0.8, -0.8>,
  <-0.4, -0.3>, <0.4, -0.3>, <0.4, 0.3>, <-0.4, 0.3>, <-0.4, -0.3>
  pigment { rgb <0.9, 0.5, 0.2> } rotate x*80 translate <-1.2, 1.8, 0> }
polygon { 4, <-0.7, -0.6>, <0.7, -0.6>, <0, 0.7>, <-0.7, -0.6>
  pigment { rgbf <0.3, 0.6, 1, 0.8> } rotate x*70 rotate y*20 translate <1.2, 1.5, -0.4> }
polygon { 5, <0, 0>, <1.5, 0>, <1.5, 1>, <0, 1>, <0, 0>
  pigment { rgb <0.4, 0.85, 0.4> } rotate x*90 translate <-0.9, 0.6, -0.3> }
sphere { <0.9, 0.5, 0.4>, 0.5 pigment { rgb <0.9, 0.9, 0.9> } }
box { <-2.4, 0, 0.6>, <-1.6, 0.5, 1.4> pigment { rgb <0.8, 0.3, 0.3> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
