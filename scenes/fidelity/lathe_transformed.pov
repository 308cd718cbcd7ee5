// povml fidelity scene: lathe_transformed
// Rule: Lathe::Transform: rotated, scaled non-uniformly and moved, the ray renormalised in lathe space
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
lathe { cubic_spline 7, <0,-0.5>, <0,0>, <0.8,0.2>, <0.3,1>, <0.7, 1.6>, <0, 2>, <0, 2.5> rotate <0, 0, 70> scale <0.7, 1, 1.4> translate <-1.3, 0.9, 0> pigment { rgb <0.3,0.5,1> } }
lathe { quadratic_spline 6, <0,0>, <0.8,0>, <0.4,1>, <0.8, 1.5>, <0.3, 2>, <0, 2.2> scale <1.3, 0.6, 0.8> rotate x*-30 translate <1.4, 0.3, 0> pigment { rgb <0.2,1,0.4> } }
