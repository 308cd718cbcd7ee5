// povml fidelity scene: sweep_shadow
// Rule: shadow rays meet sphere sweeps between the point and the light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 8, -2>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
sphere_sweep { linear_spline 4, <-2, 1.5, 0>, 0.15, <-1, 2, 0>, 0.25, <0, 1.5, -0.5>, 0.15, <0, 2, 0.5>, 0.1 pigment { rgb <0.9, 0.3, 0.2> } }
sphere_sweep { b_spline 5, <0.5, 1.5, 0>, 0.2, <1, 2.2, 0>, 0.2, <1.5, 1.5, 0.5>, 0.2, <2, 2.2, 0.5>, 0.2, <2.5, 1.5, 0>, 0.2 pigment { rgb <0.3, 0.5, 0.9> } }
sphere { <1.5, 0.5, 0.8>, 0.5 pigment { rgb <0.3, 0.8, 0.4> } }
