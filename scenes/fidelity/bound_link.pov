// clipped_by { bounded_by } clips by the bounding objects; bounded_by { clipped_by } bounds by
// the clip objects; the bounding objects move with the object's later transforms
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <4, 6, -5> rgb 1 }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.8 } }
sphere { 0, 1 pigment { rgb <1, 0.4, 0.2> } bounded_by { box { <-0.7, -1, -0.7>, <0.7, 0.6, 0.7> } } clipped_by { bounded_by } translate <-2, 0.5, 0> }
union { sphere { 0, 1 } sphere { y, 0.5 } pigment { rgb <0.3, 1, 0.3> } clipped_by { box { -0.75, 0.75 rotate 30*y } } bounded_by { clipped_by } translate <0, 0.5, 0> }
cylinder { -y, y, 0.8 pigment { rgb <0.4, 0.4, 1> } clipped_by { sphere { 0, 1 } } bounded_by { box { -1, 1 } scale <1, 0.5, 1> } rotate 30*z translate <2, 0.5, 0> }
