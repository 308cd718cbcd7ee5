// The random table and the wave sources: cells is PatternRands(Hash3d(floor(p + 1e-10))) (min 1),
// ripples and waves sum over the 10 default wave sources and frequencies (Initialize_Waves).
// Run: povray +Irandom.pov +O/tmp/t.png +W8 +H6 -D   (the values go to #debug)
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
camera { location -z look_at 0 }
#declare P = array[12] { <0.5, 0.5, 0.5>, <1.5, 0.5, 0.5>, <-0.5, -0.5, -0.5>, <3.2, -7.9, 11.1>, <100.5, 200.5, -300.5>, <4095.5, 4096.5, 8191.5>, <-4096.5, 12345.5, -54321.5>, <0, 0, 0>, <-1, 2, -3>, <77.7, 88.8, 99.9>, <-1000.25, 0.75, 1000.25>, <2, 2, 2> }
#ifdef (F) #undef F #end
#declare F = function { pattern { cells frequency 0 } }
#for (I, 0, 11)
  #debug concat("C ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#declare Q = array[6] { <0.3, 0.4, 0.5>, <0, 0, 0>, <1.5, -2.5, 3.5>, <-12.5, 3.25, 7.75>, <100.1, -200.2, 300.3>, <0.01, 0.02, -0.03> }
#declare R = function { pattern { ripples ramp_wave } }
#declare W = function { pattern { waves ramp_wave } }
#for (I, 0, 5)
  #debug concat("R ", str(I, 0, 0), " ", str(R(Q[I].x, Q[I].y, Q[I].z), 0, 20), "\n")
  #debug concat("W ", str(I, 0, 0), " ", str(W(Q[I].x, Q[I].y, Q[I].z), 0, 20), "\n")
#end
