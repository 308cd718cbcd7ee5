// povml fidelity scene: prism_knot
// Rule: the stiff case of a prism seen along its outline's knots and edges: the camera level
//       with the cap (y = 1), rays along the vertical edges where two segments meet (both roots,
//       w = 1 and w = 0, at one depth) and grazing the cap plane
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 1, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
prism { linear_spline 0, 1, 5, <-0.6,-0.6>, <0.6,-0.6>, <0.6,0.6>, <-0.6,0.6>, <-0.6,-0.6> pigment { rgb <1,0.4,0.2> } rotate y*45 translate <-1.4, 0, 0> }
prism { quadratic_spline 0, 1, 6, <0,-1>, <0.8,0>, <0,0.8>, <-0.8,0>, <0.8,0>, <0,0.8> pigment { rgb <0.2,1,0.4> } translate <1.3, 0, 0> }
