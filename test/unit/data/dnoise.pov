// DNoise and DTurbulence through a turbulence warp on gradient x, y and z: with frequency 0 the
// value is the warped coordinate p + DTurbulence(p)·<1,1,1> (above 1 reduced by fmod 1, negatives
// wrapped into [0,1)). Octaves 1 is DNoise itself.
// Run: povray +Idnoise.pov +O/tmp/t.png +W8 +H6 -D   (the values go to #debug)
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
camera { location -z look_at 0 }
#declare P = array[10] { <0.3, 0.4, 0.5>, <0, 0, 0>, <-0.5, 0.25, -0.75>, <1.5, -2.5, 3.5>, <12.345, -67.891, 23.456>, <-1234.5678, 0.4321, 876.5>, <0.123, 99999.9, -0.456>, <6, -7, 8>, <-0.9999999999, 0.7, -2>, <4095.5, -4096.5, 0.25> }
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { turbulence <1, 1, 1> octaves 1 omega 0.5 lambda 2 } frequency 0 } }
#for (I, 0, 9)
  #debug concat("D 0 x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { turbulence <1, 1, 1> octaves 1 omega 0.5 lambda 2 } frequency 0 } }
#for (I, 0, 9)
  #debug concat("D 0 y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { turbulence <1, 1, 1> octaves 1 omega 0.5 lambda 2 } frequency 0 } }
#for (I, 0, 9)
  #debug concat("D 0 z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { turbulence <1, 1, 1> octaves 6 omega 0.5 lambda 2 } frequency 0 } }
#for (I, 0, 9)
  #debug concat("D 1 x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { turbulence <1, 1, 1> octaves 6 omega 0.5 lambda 2 } frequency 0 } }
#for (I, 0, 9)
  #debug concat("D 1 y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { turbulence <1, 1, 1> octaves 6 omega 0.5 lambda 2 } frequency 0 } }
#for (I, 0, 9)
  #debug concat("D 1 z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { turbulence <1, 1, 1> octaves 3 omega 0.6 lambda 2.5 } frequency 0 } }
#for (I, 0, 9)
  #debug concat("D 2 x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { turbulence <1, 1, 1> octaves 3 omega 0.6 lambda 2.5 } frequency 0 } }
#for (I, 0, 9)
  #debug concat("D 2 y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { turbulence <1, 1, 1> octaves 3 omega 0.6 lambda 2.5 } frequency 0 } }
#for (I, 0, 9)
  #debug concat("D 2 z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
