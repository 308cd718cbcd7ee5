// povml fidelity scene: prism_shadow
// Rule: prisms in shadow rays: an opaque and a filtered prism shadow the floor and each other, the self-shadowed concave sides
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
light_source { <6, 3, 1>, rgb 0.4 }
prism { quadratic_spline 0, 1.6, 6, <0,-1>, <0.8,0>, <0,0.8>, <-0.8,0>, <0.8,0>, <0,0.8> pigment { rgb <1,0.5,0.2> } translate <-1, 0, 0.3> }
prism { linear_spline 0.5, 0.8, 7, <-1,-0.6>, <1,-0.6>, <1,0.6>, <0.2,0.6>, <0.2,0>, <-1,0>, <-1,-0.6> pigment { rgbf <0.3,0.6,1,0.7> } translate <1.2, 0, -0.8> }
sphere { <1.3, 0.3, 0.8>, 0.3 pigment { rgb 1 } }
