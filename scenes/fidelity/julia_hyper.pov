// povml fidelity scene: julia_hyper
// Rule: the hypercomplex algebra (hcmplx.cpp): sqr, cube (z^2 by HSqr) and the step from the
//       slope toward the surface, radius 4, escape 16; a slice off w = 0. (The reciprocal map
//       is in test_julia.ml, the function maps in julia_func.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -3.2> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.4,0.4,0.5> } }
julia_fractal { <-0.4, 0.4, 0.1, 0> hypercomplex sqr max_iteration 6 precision 30 scale 0.35 translate <-1.2, 0.2, 0> pigment { rgb <1, 0.5, 0.3> } }
julia_fractal { <-0.3, 0.5, 0.1, 0> hypercomplex cube max_iteration 6 precision 30 scale 0.35 translate <0, 0.4, 0.3> pigment { rgb <0.3, 1, 0.5> } }
julia_fractal { <-0.2, 0.1, 0.1, 0.05> hypercomplex max_iteration 5 precision 25 slice <0.2, 0.1, 0, 1>, 0.05 scale 0.3 translate <0, -0.6, -0.8> pigment { rgb <1, 1, 0.3> } }
