// povml fidelity scene: prism_csg
// Rule: Prism::Inside (in_curve: the crossings towards +u, between height1 and below height2) in difference and intersection, inverse prisms, and every hit of a member pushed
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
difference {
  prism { cubic_spline 0, 1.5, 8, <0,-1.2>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1>, <-1, 0.3> }
  sphere { <0.3, 1.5, -0.5>, 0.8 }
  pigment { rgb <0.2,1,0.4> } translate <-1.8, 0, 0.5> }
intersection {
  sphere { <0, 0.6, 0>, 0.9 }
  prism { conic_sweep linear_spline 0.2, 1, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> rotate x*180 translate y*1.5 }
  pigment { rgb <1,0.4,0.2> } translate <1.6, 0, 0.5> }
intersection { box { <-0.7, 0, -0.5>, <0.7, 0.9, 0.5> } prism { linear_spline -1, 1, 4, <-0.3,-0.3>, <0.3,-0.3>, <0,0.3>, <-0.3,-0.3> inverse } pigment { rgb <0.9, 0.9, 0.3> } rotate y*30 translate <0, 0, -1.8> }
