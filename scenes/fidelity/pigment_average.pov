// An average pigment: the entries' colours weighed by their values (a value may be left out)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }

plane { y, 0 pigment { average pigment_map { [1 gradient x color_map { [0 rgb <1,0,0>] [1 rgb 0] }] [2 checker rgb <0,0,1>, rgb 1] [bozo scale 0.3] } } }
sphere { <0, 1, 0>, 1 pigment { average pigment_map { [1 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] } } }
