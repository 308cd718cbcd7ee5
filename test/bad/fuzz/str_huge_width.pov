#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
#debug concat("Big = ", str(1e999999, 12345678901234567890, 3), "\n")
sphere { 0, 1 pigment { rgb 1 } }
// (found by fuzzing) The width 12345678901234567890 becomes C's -2147483648: a string of 2 GiB of
// zeros, which took 12 s. It is a limit error before the string is made.
