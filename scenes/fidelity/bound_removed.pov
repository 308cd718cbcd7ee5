// bounded_by on top-level primitives: POV-Ray removes the bounding objects (Link_To_Frame) but a
// smaller bounding box stays the object's box, so rays that miss it miss the object
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <4, 6, -5> rgb 1 }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.8 } }
sphere { <-2, 0.5, 0>, 1 pigment { rgb <1, 0.2, 0.2> } bounded_by { box { <-2.5, 0, -1>, <-1.5, 1.2, 1> } } }
sphere { <0, 0.5, 0>, 1 pigment { rgb <0.2, 1, 0.2> } bounded_by { sphere { <0, 0.5, 0>, 3 } } }
cone { <2, -0.5, 0>, 1, <2, 1.5, 0>, 0 pigment { rgb <0.3, 0.3, 1> } bounded_by { box { <1, -1, -1>, <3, 0.8, 1> rotate 20*z } } }
