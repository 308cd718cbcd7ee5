// povml fidelity scene: sweep_csg
// Rule: SphereSweep::Inside: some segment has a sphere holding the point (a root in [0, 1] of
//       |P − C(u)|² − R(u)², degree 2 or 6), negated by inverse; in a CSG every kept hit is
//       pushed with its normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
difference {
  box { <-1, 0, -0.6>, <1, 1.5, 0.6> }
  sphere_sweep { linear_spline 3, <-1.2, 0.3, -0.7>, 0.35, <0, 1.2, 0>, 0.45, <1.2, 0.3, -0.7>, 0.35 }
  translate <-2.2, 0, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
intersection {
  sphere { <0, 0.9, 0>, 0.9 }
  sphere_sweep { cubic_spline 6, <-1, 0, 0>, 0.3, <-0.6, 0.4, 0>, 0.4, <0, 1, 0>, 0.5, <0.6, 1.4, 0>, 0.4, <0.9, 1.8, 0>, 0.3, <1.2, 2, 0>, 0.2 }
  translate <0, 0, 0.5> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
difference {
  sphere_sweep { b_spline 6, <0, 0, 0>, 0.4, <0, 0.5, 0>, 0.5, <0.5, 1, 0>, 0.5, <1, 1.2, 0>, 0.5, <1.5, 1, 0>, 0.4, <2, 0.5, 0>, 0.3 }
  box { <-1, 0.5, -1>, <3, 3, -0.1> }
  translate <1.3, 0, 0> pigment { rgb <0.3, 0.5, 0.9> } }
intersection {
  box { <-0.8, 0, -0.5>, <0.8, 0.7, 0.5> }
  sphere_sweep { linear_spline 2, <-1, 0.35, 0>, 0.25, <1, 0.35, 0>, 0.3 inverse }
  translate <0, 0, -2.2> pigment { rgb <0.9, 0.8, 0.3> } }
