#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
#declare A = array[3] { 1, 2, 3 }
#declare N = 1e400 - 1e400;
sphere { 0, A[N] }
