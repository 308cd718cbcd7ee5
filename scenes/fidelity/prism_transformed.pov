// povml fidelity scene: prism_transformed
// Rule: Prism::Transform: rotate, non-uniform scale, translate and a matrix composed into the prism's transform; the conic sweep's normal with P.y from the point in prism space
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
prism { cubic_spline -0.5, 0.5, 8, <0,-0.9>, <0.8,0>, <0,0.8>, <-0.8,0>, <0,-0.8>, <0.8,0>, <0,0.8>, <-0.8, 0.3> rotate <70, 20, 0> scale <1, 0.5, 1.5> translate <-1.6, 1, 0> pigment { rgb <0.3,0.5,1> } }
prism { conic_sweep quadratic_spline 0.3, 1, 6, <0,-1>, <0.8,0>, <0,0.8>, <-0.8,0>, <0.8,0>, <0,0.8> scale <1.2, 1.5, 0.7> rotate z*30 translate <1.4, 0.2, 0> pigment { rgb <0.2,1,0.4> } }
prism { linear_spline 0, 0.3, 4, <-0.7,-0.7>, <0.7,-0.7>, <0,0.7>, <-0.7,-0.7> matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0> translate <0, 0, -2> pigment { rgb <1,0.4,0.2> } }
