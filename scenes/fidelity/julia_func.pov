// povml fidelity scene: julia_func
// Rule: the hypercomplex function maps (hcmplx.cpp): f applied through the duplex form (HFunc),
//       Iteration_HCompl_Func reading the point's y for its z while D_Iteration_HCompl_Func reads
//       z, and the normal of f (not f') computed at the crossing from the stack as the march
//       left it (after an escaped Iteration, what deeper iterations left beyond the escape).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -3.2> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.4,0.4,0.5> } }
julia_fractal { <0.5, 0.2, 0.1, 0.0> hypercomplex sin max_iteration 5 precision 30 scale 0.3 translate <-0.6, -0.6, -0.8> pigment { rgb <1, 1, 0.3> } }
julia_fractal { <0.2, 0.3, 0.1, 0.0> hypercomplex pwr(2, 0.5) max_iteration 5 precision 30 scale 0.3 translate <0.6, -0.6, -0.8> pigment { rgb <1, 0.4, 1> } }
julia_fractal { <0.3, 0.2, 0.1, 0.1> hypercomplex exp max_iteration 5 precision 30 scale 0.3 translate <-1.2, 0.2, 0> pigment { rgb <0.5, 1, 1> } }
julia_fractal { <0.3, 0.2, 0.1, 0.1> hypercomplex cosh max_iteration 4 precision 30 scale 0.3 translate <0.1, 0.3, 0> pigment { rgb <1, 0.6, 0.4> } }
