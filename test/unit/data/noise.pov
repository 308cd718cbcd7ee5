// POV-Ray 3.7's Noise at points chosen to cover negative, large, near-integer and integer
// coordinates, for noise generators 1, 2 and 3 (f_noise_generator passes its 4th argument as the
// generator). Run: povray +Inoise.pov +O/tmp/noise.png +W8 +H6 -D   (the values go to #debug).
// The last block checks that f_noise3d uses the scene's generator (set to 1 here).
#version 3.7;
global_settings { assumed_gamma 1 noise_generator 1 }
#include "functions.inc"
#declare P = array[38] {
  <0, 0, 0>, <0.5, 0.5, 0.5>, <0.3, 0.4, 0.5>, <1, 2, 3>, <-1, -2, -3>,
  <-0.5, 0.25, -0.75>, <1.5, -2.5, 3.5>, <0.999999, 1.000001, 2.0000001>,
  <-0.9999999999, -1.00000000001, 0.5>, <-0.00000001, 0.00000001, 0.7>,
  <12.345, -67.891, 23.456>, <1000.1, 2000.2, -3000.3>, <-1234.5678, 4321.8765, 0.1234>,
  <99999.9, -54321.123, 12345.678>, <100000, 100000, 100000>, <-100000.25, 50000.75, -75000.5>,
  <4095.5, 4096.5, -4096.5>, <10000, -10000, 10000.5>, <0.1, 0.2, 0.3>, <-0.1, -0.2, -0.3>,
  <7.77, 8.88, 9.99>, <-3.14159, 2.71828, 1.41421>, <0.25, -0.25, 0.125>, <2.5, 2.5, -2.5>,
  <33.3, -44.4, 55.5>, <-0.7, 0, 0.7>, <6, -7, 8>, <0.000123, 45.6, -78.9>,
  <20000.125, -30000.0625, 40000.03125>, <-5.5, -6.5, -7.5>, <-10000.5, -9999.5, -10001>,
  <1e9, -1e9, 0.5>, <3e9, -3e9, 0.25>, <1e17, -1e17, 2.5>, <-2147483648.5, 2147483647.5, 0.3>,
  <0.0001, -0.0001, 0.00005>, <-4096, 4096, -8192>, <0.75, 123456.789, -0.333>
}
#for (G, 1, 3)
  #for (I, 0, dimension_size(P, 1) - 1)
    #debug concat("N ", str(G, 0, 0), " ", str(I, 0, 0), " ", str(f_noise_generator(P[I].x, P[I].y, P[I].z, G), 0, 20), "\n")
  #end
#end
#for (I, 0, 5)
  #debug concat("S ", str(I, 0, 0), " ", str(f_noise3d(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
camera { location -z look_at 0 }
