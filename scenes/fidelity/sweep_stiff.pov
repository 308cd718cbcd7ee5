// povml fidelity scene: sweep_stiff
// Rule: the stiff cases of sphsweep.cpp: a linear segment seen along its axis (its side slope
//       below 1e-4, met as the sphere at its root), rays tangent to the tube (an orthographic
//       camera), coincident modeling spheres (a segment of length 0), a cone-like segment
//       whose radius grows faster than its centre moves (one sphere inside the next), the
//       first and last crossings always kept by Find_Valid_Points, and a large tolerance.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0.5, -6> look_at <0, 0.5, 0> right 6*x*image_width/image_height up 6*y }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
sphere_sweep { linear_spline 2, <-2, 1, -1>, 0.5, <-2, 1, 1>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
sphere_sweep { linear_spline 3, <-1, 0, 0>, 0.3, <-1, 0, 0>, 0.3, <0, 1, 0>, 0.4 pigment { rgb <0.3, 0.8, 0.4> } }
sphere_sweep { linear_spline 2, <1, 0.5, 0>, 0.1, <1.5, 0.5, 0>, 1.0 pigment { rgb <0.3, 0.5, 0.9> } }
sphere_sweep { cubic_spline 4, <-2, -1.5, 0>, 0.3, <-1, -1, 0>, 0.3, <1, -1, 0>, 0.3, <2, -1.5, 0>, 0.3 pigment { rgb <0.9, 0.8, 0.3> } }
sphere_sweep { b_spline 4, <-2, -2, 0>, 0.2, <-1, -2, 0>, 0.2, <1, -2, 0>, 0.2, <2, -2, 0>, 0.2 tolerance 0.5 pigment { rgb <0.8, 0.5, 0.9> } }
sphere_sweep { linear_spline 2, <2.2, 2, 0>, 0.4, <2.2, 1.2, 0>, 0.4 pigment { rgb <0.5, 0.9, 0.9> } }
