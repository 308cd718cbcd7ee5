#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
// a count far beyond the points given: the error is at the first point missing
sphere_sweep { linear_spline 2147483647, <-1, 1, 3>, 0.3, <1, 1, 3>, 0.4 pigment { rgb 1 } }
