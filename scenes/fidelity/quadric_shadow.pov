// povml fidelity scene: quadric_shadow
// Rule: quadrics in shadow rays (docs/povray-rules.md §4): a shadow ray from a quadric's own surface
//       finds a root at ≈ 0, under the 1e-3 shadow tolerance, and its far root beyond it (a
//       concave part shadows itself); opaque and filtered quadrics shadow the floor, each other
//       and a sphere; an unbounded cylinder's shadow runs to the horizon.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
light_source { <6, 3, 1>, rgb 0.4 }
// an opaque ellipsoid
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 scale <0.6, 0.4, 0.5> translate <-1.4, 0.9, 0>
  pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.5 } }
// a filtered saddle-shaped sheet: y = x² − z², clipped to a disc of radius 0.8
quadric { <1, 0, -1>, <0, 0, 0>, <0, -1, 0>, 0
  clipped_by { quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.64 } quadric { <0, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 } }
  pigment { rgbf <0.3, 0.6, 1, 0.7> } translate <1.2, 1.2, -0.3> }
// an unbounded cylinder along x, high above the floor
quadric { <0, 1, 1>, <0, 0, 0>, <0, -4, -5>, 4 + 6.25 - 0.04 pigment { rgb <0.4, 0.85, 0.4> } }
sphere { <0.3, 0.5, 0.6>, 0.5 pigment { rgb <0.9, 0.9, 0.9> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
