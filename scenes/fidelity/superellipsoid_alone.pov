// povml fidelity scene: superellipsoid_alone
// Rule: superellipsoid { <e, n> } is (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 within the box
//       ±1 (super.cpp): the ray is clipped to the box ±1.01, cut at the planes x = ±y, x = ±z,
//       y = ±z, x = 0, y = 0, z = 0, and each piece searched by secant and bisection steps
//       (solve_hit1) or, without a sign change, by secant steps (check_hit2); hits beyond 1e-4;
//       the normal is POV-Ray's closed form of the gradient. Powers 1 to 6 are multiplied out.
// A rounded box, a pillow, a star-like shape, a cylinder-like one and a sphere (e = n = 1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
superellipsoid { <0.2, 0.2> translate <-2.4, 1, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
superellipsoid { <1, 0.3> translate <0, 1, 0> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
superellipsoid { <2.5, 2.5> scale 1.2 translate <2.4, 1.2, 0> pigment { rgb <0.3, 0.5, 0.9> } }
superellipsoid { <0.05, 1> translate <-1.2, 0.6, 2.5> pigment { rgb <0.9, 0.8, 0.3> } }
superellipsoid { <1, 1> scale 0.6 translate <1.3, 0.6, 2.2> pigment { rgb <0.8, 0.5, 0.9> } finish { phong 0.4 } }
superellipsoid { <0.5, 3> scale 0.5 translate <0, 0.5, -2> pigment { rgb <0.5, 0.9, 0.9> } }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
