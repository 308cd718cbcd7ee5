// povml fidelity scene: lathe_knot
// Rule: the stiff case of a lathe seen at a spline knot: the camera at the height of the knots
//       (y = 1) looking level, rays grazing the joins of the segments (w = 1 of one, w = 0 of
//       the next), the bounding cylinders' shared heights and radii, and the parallel-ray
//       quadratic of lathe.cpp (|D.y| ≤ EPSILON)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 1, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
lathe { linear_spline 5, <0,0>, <1,0.5>, <0.6,1>, <1,1.5>, <0,2> pigment { rgb <1,0.4,0.2> } translate -1.3*x }
lathe { cubic_spline 6, <0,-0.5>, <0.2,0>, <1,1>, <0.5,1.5>, <0.2,2>, <0,2.5> pigment { rgb <0.3,0.5,1> } translate 1.3*x }
lathe { quadratic_spline 5, <0,0.5>, <0.5,0.5>, <0.3,1>, <0.5,1.5>, <0,1.5> pigment { rgb <0.2,1,0.4> } scale 0.8 translate <0, 0.2, -1.5> }
