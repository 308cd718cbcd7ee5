// texture.cpp's waveforms with negative arguments: ripples with phase -3.7 (cycloidal of negative
// indices), wood with turbulence (cycloidal((x + DTurbulence.x)·t), mostly negative) and spiral2
// below z = 0 (Triangle_Wave of negative values); frequency 0 and ramp_wave for wood and spiral2,
// so their values are the raw pattern values.
// Run: povray +Iwaveforms.pov +O/tmp/t.png +W8 +H6 -D   (the values go to #debug)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location -z look_at 0 }
#declare P = array[8] { <0.3, 0.4, 0.5>, <-1.2, 0.7, -2.5>, <2.25, -3.5, -0.75>, <-0.1, -0.2, -7.3>,
  <12.5, -7.25, 3.125>, <-0.05, 0.6, -0.45>, <5.5, 5.5, -5.5>, <-3.3, -4.4, 1.1> }
#declare R = function { pattern { ripples phase -3.7 ramp_wave } }
#declare W = function { pattern { wood turbulence <0.8, 1.3, 0> octaves 3 frequency 0 ramp_wave } }
#declare S = function { pattern { spiral2 3 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("R ", str(I, 0, 0), " ", str(R(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
  #debug concat("W ", str(I, 0, 0), " ", str(W(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
  #debug concat("S ", str(I, 0, 0), " ", str(S(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
