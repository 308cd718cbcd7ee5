// povml fidelity scene: prism_alone
// Rule: prism.cpp: each spline type (linear, quadratic, cubic, Bezier) with a linear and a conic sweep, closed and open, caps and sides; the normal from the segment's derivative at the hit's parameter
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
prism { linear_spline 0, 1, 5, <-0.6,-0.6>, <0.6,-0.6>, <0.6,0.6>, <-0.6,0.6>, <-0.6,-0.6> pigment { rgb <1,0.4,0.2> } translate <-2.2, 0, 0.8> }
prism { quadratic_spline 0, 1.2, 6, <0,-1>, <0.8,0>, <0,0.8>, <-0.8,0>, <0.8,0>, <0,0.8> pigment { rgb <0.2,1,0.4> } translate <0, 0, 1.2> }
prism { cubic_spline 0, 0.8, 8, <0,-0.9>, <0.8,0>, <0,0.8>, <-0.8,0>, <0,-0.8>, <0.8,0>, <0,0.8>, <-0.8, 0.3> pigment { rgb <0.3,0.5,1> } translate <2.2, 0, 0.8> }
prism { bezier_spline 0, 0.5, 8, <0,0>,<0.8,0>,<0.8,0.8>,<0,0.8>, <0,0.8>,<-0.8,0.8>,<-0.8,0>,<0,0> pigment { rgb <1,1,0.3> } translate <-1.4, 0, -1.5> }
prism { conic_sweep linear_spline 0.4, 1, 4, <-0.7,-0.7>, <0.7,-0.7>, <0,0.7>, <-0.7,-0.7> pigment { rgb <1,0.5,0.8> } rotate x*180 translate <0.5, 1, -1.3> }
prism { linear_spline 0, 0.6, 5, <-0.4,-0.4>, <0.4,-0.4>, <0.4,0.4>, <-0.4,0.4>, <-0.4,-0.4> open pigment { rgb <0.6,0.9,0.9> } translate <2.2, 0, -1.3> }
