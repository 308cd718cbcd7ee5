// povml fidelity scene: lathe_alone
// Rule: lathe.cpp: linear (quadratic equation), quadratic (quartic), cubic and Bezier (degree 6, Sturm) splines, the bounding cylinders of bcyl.cpp, the normal rotated from the curve's derivative
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
lathe { linear_spline 5, <0,0>, <0.8,0>, <1,1>, <0.4, 1.5>, <0, 2> pigment { rgb <1,0.4,0.2> } translate <-2.4, 0, 0.5> }
lathe { quadratic_spline 6, <0,0>, <0.8,0>, <0.4,1>, <0.8, 1.5>, <0.3, 2>, <0, 2.2> pigment { rgb <0.2,1,0.4> } translate <-0.8, 0, 0.5> }
lathe { cubic_spline 7, <0,-0.5>, <0,0>, <0.8,0.2>, <0.3,1>, <0.7, 1.6>, <0, 2>, <0, 2.5> pigment { rgb <0.3,0.5,1> } translate <0.8, 0, 0.5> }
lathe { bezier_spline 8, <0,0>, <1,0>, <1,1>, <0.5,1>, <0.5,1>, <0,1>, <0.8,2>, <0,2> pigment { rgb <1,1,0.3> } scale 0.8 translate <2.4, 0, 0.5> }
lathe { linear_spline 4, <0.5,0>, <0.7,0.3>, <0.3,0.6>, <0.5,0> sturm pigment { rgb <1,0.5,0.8> } translate <0, 0, -1.8> }
