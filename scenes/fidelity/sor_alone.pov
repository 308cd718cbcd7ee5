// povml fidelity scene: sor_alone
// Rule: sor.cpp: the cubic radius² per segment (MInvers of its 4×4 system), the base and cap discs, open, sturm, the bounding cylinders
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
sor { 7, <0,0>, <0.6,0>, <1,0.5>, <0.5,1>, <0.8,1.5>, <0.4,2>, <0,2.5> pigment { rgb <1,0.4,0.2> } translate <-2, 0, 0.5> }
sor { 6, <0,-0.2>, <0.8,0>, <0.3,0.7>, <0.9,1.4>, <0.5,2>, <0.5,2.2> open pigment { rgb <0.2,1,0.4> } translate <0, 0, 0.5> }
sor { 5, <0,-0.2>, <0.8,0>, <0.3,0.7>, <0.9,1.4>, <0.5,2> sturm pigment { rgb <0.3,0.5,1> } translate <2, 0, 0.5> }
