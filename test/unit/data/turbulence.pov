// Turbulence through the marble pattern: with turbulence <1,0,0>, frequency 0 and ramp_wave its
// value is x + Turbulence(p) (negatives wrapped into [0,1)), for each noise generator.
// Run: povray +Iturbulence.pov +O/tmp/t.png +W8 +H6 -D   (the values go to #debug)
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
camera { location -z look_at 0 }
#declare P = array[8] { <0, 0, 0>, <0.3, 0.4, 0.5>, <-1.5, 2.25, -3.75>, <12.345, -67.891, 23.456>, <1000.1, 2000.2, -3000.3>, <-99999.9, 54321.123, -12345.678>, <6, -7, 8>, <0.999999, -1.000001, 0.5> }
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 1 omega 0.5 lambda 2 noise_generator 1 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 1 0 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 3 omega 0.5 lambda 2 noise_generator 1 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 1 1 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 6 omega 0.5 lambda 2 noise_generator 1 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 1 2 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 10 omega 0.7 lambda 2.3 noise_generator 1 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 1 3 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 4 omega 0.35 lambda 3.1 noise_generator 1 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 1 4 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 1 omega 0.5 lambda 2 noise_generator 2 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 2 0 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 3 omega 0.5 lambda 2 noise_generator 2 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 2 1 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 6 omega 0.5 lambda 2 noise_generator 2 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 2 2 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 10 omega 0.7 lambda 2.3 noise_generator 2 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 2 3 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 4 omega 0.35 lambda 3.1 noise_generator 2 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 2 4 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 1 omega 0.5 lambda 2 noise_generator 3 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 3 0 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 3 omega 0.5 lambda 2 noise_generator 3 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 3 1 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 6 omega 0.5 lambda 2 noise_generator 3 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 3 2 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 10 omega 0.7 lambda 2.3 noise_generator 3 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 3 3 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <1, 0, 0> octaves 4 omega 0.35 lambda 3.1 noise_generator 3 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("T 3 4 ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
