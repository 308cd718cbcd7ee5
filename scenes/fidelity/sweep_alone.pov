// povml fidelity scene: sweep_alone
// Rule: sphere_sweep { linear_spline | cubic_spline | b_spline N, C1, R1, … } (sphsweep.cpp):
//       segments are centre and radius polynomials in u ∈ [0, 1] (SphereSweep::Compute, the
//       Catmull-Rom and B-spline matrices); a ray meets the single spheres, each segment's two
//       closing planes and its sides (a quadratic for linear segments, a degree-10 polynomial
//       through bezier_01 and Solve_Polynomial for cubic ones, each root's sphere then met as a
//       sphere); hits sorted, those inside the sweep dropped (Find_Valid_Points), kept beyond
//       the tolerance (1e-6 by default). A linear segment whose side slope is below 1e-4 is met
//       as the sphere at its root.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
sphere_sweep { linear_spline 4, <-3, 0.5, 0>, 0.3, <-2, 1.5, 0>, 0.5, <-1, 0.5, 0.5>, 0.2, <-1.5, 0.3, -1>, 0.3
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
sphere_sweep { cubic_spline 6, <0, 0, 0>, 0.2, <0, 0.5, 0>, 0.3, <1, 1.5, 0>, 0.3, <2, 0.8, 0>, 0.4, <2.5, 1.5, 0.5>, 0.2, <3, 2, 0>, 0.1
  pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
sphere_sweep { b_spline 5, <-2, 0, -2>, 0.2, <-1, 0.5, -2>, 0.3, <0, 0.2, -2.5>, 0.3, <1, 0.8, -2>, 0.3, <2, 0.2, -2>, 0.2
  tolerance 1e-4 pigment { rgb <0.3, 0.5, 0.9> } }
sphere_sweep { linear_spline 2, <1, 0.4, 2>, 0.4, <3, 0.4, 2.5>, 0.4 pigment { rgb <0.9, 0.8, 0.3> } }
sphere_sweep { linear_spline 3, <-2.5, 0.3, 2>, 0.1, <-1.5, 1.5, 2>, 0.6, <-0.5, 0.3, 2.5>, 0.1 pigment { rgb <0.8, 0.5, 0.9> } }
