// Written by gen.py (beside it); run: povray +Ipattern_values_f1.pov +O/tmp/t.png +W8 +H6 -D  (values go to #debug)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location -z look_at 0 }
#declare P_g3 = array[8] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25> }
#declare P_frac = array[12] {
  <0.3, 0.4, 0.0>,
  <-0.75, 0.1, 0.0>,
  <-1.2, 0.35, 0.0>,
  <0.1, 0.62, 0.0>,
  <-0.5, -0.5, 0.0>,
  <0.28, 0.01, 0.0>,
  <-1.9, 0.0, 0.0>,
  <0.45, -0.3, 0.0>,
  <-0.2, 0.1, 0.0>,
  <-1.0, 0.05, 0.0>,
  <0.2, -0.1, 0.0>,
  <-0.1, -0.7, 0.0> }
#declare P_magnet = array[10] {
  <0.5, 0.5, 0.0>,
  <1.2, -0.3, 0.0>,
  <2.5, 0.8, 0.0>,
  <-0.5, 1.1, 0.0>,
  <1.9, 0.05, 0.0>,
  <0.0, 0.0, 0.0>,
  <3.1, -1.2, 0.0>,
  <1.05, 1.5, 0.0>,
  <1.4, 0.2, 0.0>,
  <0.9, -0.9, 0.0> }
#declare P_xz = array[40] {
  <2.548, 0.37, -5.718>,
  <1.649, 0.37, 4.787>,
  <4.684, 0.37, 0.21>,
  <1.835, 0.37, -1.831>,
  <0.392, 0.37, -5.49>,
  <2.561, 0.37, 1.409>,
  <-3.053, 0.37, -1.7>,
  <3.306, 0.37, -0.786>,
  <6.435, 0.37, 6.598>,
  <4.737, 0.37, -5.726>,
  <-5.948, 0.37, -2.96>,
  <-1.945, 0.37, 2.869>,
  <4.576, 0.37, 0.877>,
  <1.949, 0.37, 1.023>,
  <-6.523, 0.37, 0.373>,
  <-4.015, 0.37, -1.163>,
  <-6.877, 0.37, 2.181>,
  <5.743, 0.37, -6.039>,
  <1.121, 0.37, -6.671>,
  <-2.074, 0.37, -4.77>,
  <5.048, 0.37, 3.192>,
  <5.551, 0.37, -3.949>,
  <3.065, 0.37, 2.793>,
  <0.15, 0.37, 5.827>,
  <1.749, 0.37, -3.041>,
  <3.039, 0.37, -0.263>,
  <-4.018, 0.37, 1.649>,
  <-6.324, 0.37, -0.713>,
  <0.795, 0.37, -6.964>,
  <2.08, 0.37, -5.765>,
  <2.096, 0.37, -2.224>,
  <-6.588, 0.37, 6.991>,
  <-6.102, 0.37, -4.812>,
  <0.08, 0.37, -3.568>,
  <0.426, 0.37, -0.364>,
  <1.071, 0.37, 0.611>,
  <-2.881, 0.37, -4.04>,
  <2.724, 0.37, -0.994>,
  <0.287, 0.37, 5.823>,
  <-6.881, 0.37, -3.117> }
#declare P_xz24 = array[24] {
  <2.548, 0.37, -5.718>,
  <1.649, 0.37, 4.787>,
  <4.684, 0.37, 0.21>,
  <1.835, 0.37, -1.831>,
  <0.392, 0.37, -5.49>,
  <2.561, 0.37, 1.409>,
  <-3.053, 0.37, -1.7>,
  <3.306, 0.37, -0.786>,
  <6.435, 0.37, 6.598>,
  <4.737, 0.37, -5.726>,
  <-5.948, 0.37, -2.96>,
  <-1.945, 0.37, 2.869>,
  <4.576, 0.37, 0.877>,
  <1.949, 0.37, 1.023>,
  <-6.523, 0.37, 0.373>,
  <-4.015, 0.37, -1.163>,
  <-6.877, 0.37, 2.181>,
  <5.743, 0.37, -6.039>,
  <1.121, 0.37, -6.671>,
  <-2.074, 0.37, -4.77>,
  <5.048, 0.37, 3.192>,
  <5.551, 0.37, -3.949>,
  <3.065, 0.37, 2.793>,
  <0.15, 0.37, 5.827> }
#declare P_xz200 = array[200] {
  <2.548, 0.37, -5.718>,
  <1.649, 0.37, 4.787>,
  <4.684, 0.37, 0.21>,
  <1.835, 0.37, -1.831>,
  <0.392, 0.37, -5.49>,
  <2.561, 0.37, 1.409>,
  <-3.053, 0.37, -1.7>,
  <3.306, 0.37, -0.786>,
  <6.435, 0.37, 6.598>,
  <4.737, 0.37, -5.726>,
  <-5.948, 0.37, -2.96>,
  <-1.945, 0.37, 2.869>,
  <4.576, 0.37, 0.877>,
  <1.949, 0.37, 1.023>,
  <-6.523, 0.37, 0.373>,
  <-4.015, 0.37, -1.163>,
  <-6.877, 0.37, 2.181>,
  <5.743, 0.37, -6.039>,
  <1.121, 0.37, -6.671>,
  <-2.074, 0.37, -4.77>,
  <5.048, 0.37, 3.192>,
  <5.551, 0.37, -3.949>,
  <3.065, 0.37, 2.793>,
  <0.15, 0.37, 5.827>,
  <1.749, 0.37, -3.041>,
  <3.039, 0.37, -0.263>,
  <-4.018, 0.37, 1.649>,
  <-6.324, 0.37, -0.713>,
  <0.795, 0.37, -6.964>,
  <2.08, 0.37, -5.765>,
  <2.096, 0.37, -2.224>,
  <-6.588, 0.37, 6.991>,
  <-6.102, 0.37, -4.812>,
  <0.08, 0.37, -3.568>,
  <0.426, 0.37, -0.364>,
  <1.071, 0.37, 0.611>,
  <-2.881, 0.37, -4.04>,
  <2.724, 0.37, -0.994>,
  <0.287, 0.37, 5.823>,
  <-6.881, 0.37, -3.117>,
  <1.522, -1.5, -10.704>,
  <6.095, -1.5, -2.368>,
  <-4.407, -1.5, -7.334>,
  <11.203, -1.5, -10.883>,
  <7.715, -1.5, 4.909>,
  <9.54, -1.5, 4.83>,
  <-3.673, -1.5, 1.199>,
  <10.119, -1.5, -11.019>,
  <8.399, -1.5, 4.162>,
  <-7.276, -1.5, 11.202>,
  <-4.81, -1.5, -11.89>,
  <-5.58, -1.5, 0.364>,
  <-11.333, -1.5, 2.202>,
  <-1.331, -1.5, -4.014>,
  <6.136, -1.5, 2.841>,
  <11.168, -1.5, 8.873>,
  <8.644, -1.5, 10.393>,
  <8.399, -1.5, -0.319>,
  <-10.358, -1.5, -1.27>,
  <2.87, -1.5, 11.266>,
  <3.695, -1.5, 1.782>,
  <-9.929, -1.5, 3.611>,
  <-11.112, -1.5, -8.556>,
  <-10.963, -1.5, 5.587>,
  <10.592, -1.5, 2.262>,
  <-9.901, -1.5, 5.738>,
  <-7.814, -1.5, 5.026>,
  <4.234, -1.5, 10.675>,
  <-8.029, -1.5, -6.403>,
  <-4.339, -1.5, -10.163>,
  <10.69, -1.5, 2.943>,
  <-9.45, -1.5, -0.529>,
  <-9.63, -1.5, 11.127>,
  <-3.371, -1.5, -11.939>,
  <5.766, -1.5, -4.066>,
  <3.589, -1.5, 6.777>,
  <-10.204, -1.5, 1.113>,
  <10.804, -1.5, -6.542>,
  <-6.015, -1.5, 4.175>,
  <-10.613, -1.5, 7.676>,
  <7.249, -1.5, 10.716>,
  <7.998, -1.5, 1.93>,
  <-0.957, -1.5, 0.865>,
  <3.264, -1.5, 11.44>,
  <-8.343, -1.5, -0.131>,
  <-1.201, -1.5, -6.106>,
  <-8.067, -1.5, 6.806>,
  <2.039, -1.5, 4.542>,
  <-5.826, -1.5, -0.49>,
  <-8.181, -1.5, -8.355>,
  <-8.764, -1.5, 3.572>,
  <8.342, -1.5, 1.712>,
  <6.722, -1.5, -10.112>,
  <0.438, -1.5, -8.651>,
  <0.595, -1.5, -6.027>,
  <-5.909, -1.5, 10.049>,
  <1.163, -1.5, -6.163>,
  <-0.236, -1.5, -5.174>,
  <7.079, -1.5, -2.458>,
  <8.215, -1.5, 2.268>,
  <3.635, -1.5, 2.601>,
  <2.072, -1.5, -10.496>,
  <6.969, -1.5, 2.738>,
  <-6.624, -1.5, -0.073>,
  <10.826, -1.5, 3.685>,
  <1.254, -1.5, 0.73>,
  <-10.336, -1.5, -0.087>,
  <-1.611, -1.5, 3.426>,
  <-3.31, -1.5, -8.542>,
  <8.378, -1.5, -6.036>,
  <-6.588, -1.5, -1.549>,
  <10.653, -1.5, 4.786>,
  <-8.605, -1.5, -9.707>,
  <0.01, -1.5, -10.516>,
  <-6.543, -1.5, -9.281>,
  <8.739, -1.5, 9.252>,
  <8.855, -1.5, 3.697>,
  <-11.048, -1.5, -5.398>,
  <7.874, -1.5, -11.021>,
  <-0.039, -1.5, 7.11>,
  <-5.844, -1.5, -3.675>,
  <3.257, -1.5, 3.726>,
  <-8.323, -1.5, 6.965>,
  <-10.009, -1.5, -8.145>,
  <-4.441, -1.5, -7.183>,
  <-1.062, -1.5, -3.561>,
  <5.425, -1.5, 7.597>,
  <6.523, -1.5, 8.597>,
  <-5.938, -1.5, 3.769>,
  <6.927, -1.5, 8.1>,
  <-1.898, -1.5, 9.508>,
  <-3.38, -1.5, 9.351>,
  <4.109, -1.5, -10.451>,
  <10.005, -1.5, 6.564>,
  <1.09, -1.5, 10.983>,
  <9.257, -1.5, 7.241>,
  <6.331, -1.5, 5.227>,
  <-9.208, -1.5, 2.07>,
  <-11.847, -1.5, 0.158>,
  <-7.848, -1.5, 4.867>,
  <9.959, -1.5, -7.096>,
  <1.467, -1.5, -5.127>,
  <11.435, -1.5, -0.119>,
  <-7.838, -1.5, 3.396>,
  <-0.809, -1.5, 0.425>,
  <-1.211, -1.5, -8.224>,
  <-9.145, -1.5, 2.434>,
  <-8.908, -1.5, -2.696>,
  <1.556, -1.5, 6.96>,
  <-8.25, -1.5, -2.914>,
  <-9.278, -1.5, -6.276>,
  <11.215, -1.5, 5.554>,
  <-10.361, -1.5, 11.579>,
  <-3.94, -1.5, 1.675>,
  <6.96, -1.5, -6.681>,
  <-5.109, -1.5, -4.406>,
  <2.379, -1.5, 11.297>,
  <-8.246, -1.5, 11.286>,
  <1.787, -1.5, -0.753>,
  <-10.267, -1.5, 5.146>,
  <-10.145, -1.5, 8.242>,
  <-5.498, -1.5, 7.631>,
  <6.066, -1.5, -3.145>,
  <-5.072, -1.5, 1.636>,
  <-0.854, -1.5, -2.209>,
  <11.831, -1.5, -3.814>,
  <-3.598, -1.5, 5.847>,
  <-1.302, -1.5, -5.803>,
  <-1.954, -1.5, -9.207>,
  <-8.022, -1.5, 7.608>,
  <-0.788, -1.5, -1.144>,
  <-1.114, -1.5, -7.616>,
  <-9.108, -1.5, -11.717>,
  <2.22, -1.5, -4.624>,
  <4.13, -1.5, -4.323>,
  <6.723, -1.5, 10.293>,
  <-3.069, -1.5, 2.893>,
  <-7.993, -1.5, 2.367>,
  <-5.196, -1.5, -1.242>,
  <7.771, -1.5, 8.901>,
  <-2.015, -1.5, 4.291>,
  <1.244, -1.5, -2.768>,
  <-9.977, -1.5, -10.767>,
  <-8.5, -1.5, -1.929>,
  <-4.992, -1.5, -7.493>,
  <-4.929, -1.5, -3.814>,
  <6.259, -1.5, 7.323>,
  <7.068, -1.5, 1.553>,
  <-10.965, -1.5, 7.845>,
  <6.861, -1.5, -9.264>,
  <-6.216, -1.5, -1.101>,
  <-6.937, -1.5, 11.852>,
  <3.115, -1.5, 1.701>,
  <-6.058, -1.5, -2.506>,
  <1.144, -1.5, 6.569>,
  <-3.848, -1.5, -1.858>,
  <-3.984, -1.5, -0.312>,
  <-4.315, -1.5, -6.151>,
  <1.468, -1.5, 9.696>,
  <10.859, -1.5, 10.685> }
#declare P_near_axis = array[11] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25>,
  <0.0005, 1.0, 0.0002>,
  <0.0, -2.0, 0.0>,
  <-0.0009, 0.5, -0.3> }
#declare P_g3_xz24 = array[32] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25>,
  <2.548, 0.37, -5.718>,
  <1.649, 0.37, 4.787>,
  <4.684, 0.37, 0.21>,
  <1.835, 0.37, -1.831>,
  <0.392, 0.37, -5.49>,
  <2.561, 0.37, 1.409>,
  <-3.053, 0.37, -1.7>,
  <3.306, 0.37, -0.786>,
  <6.435, 0.37, 6.598>,
  <4.737, 0.37, -5.726>,
  <-5.948, 0.37, -2.96>,
  <-1.945, 0.37, 2.869>,
  <4.576, 0.37, 0.877>,
  <1.949, 0.37, 1.023>,
  <-6.523, 0.37, 0.373>,
  <-4.015, 0.37, -1.163>,
  <-6.877, 0.37, 2.181>,
  <5.743, 0.37, -6.039>,
  <1.121, 0.37, -6.671>,
  <-2.074, 0.37, -4.77>,
  <5.048, 0.37, 3.192>,
  <5.551, 0.37, -3.949>,
  <3.065, 0.37, 2.793>,
  <0.15, 0.37, 5.827> }
#declare P_cubic = array[12] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25>,
  <1.0, 1.0, 1.0>,
  <-1.0, 0.5, -1.0>,
  <0.2, -3.0, 0.1>,
  <0.0, 0.0, -2.0> }
#declare P_g3_more = array[10] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25>,
  <0.1, 0.2, 0.3>,
  <0.5, -0.7, 0.2> }
#declare P_g3_planar = array[10] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25>,
  <0.1, 0.2, 0.3>,
  <0.0, -0.7, 0.0> }
#declare P_g3_quilt = array[9] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25>,
  <-2.0, 3.0, -1.0> }
#declare P_g3_axis = array[9] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25>,
  <0.0, 0.0, 1.5> }
#declare P_g3_cells = array[9] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25>,
  <-5e-11, 1.0, 2.99999999995> }
#declare P_crackle = array[12] {
  <0.3, 0.4, 1.7>,
  <-1.2, 0.75, 0.35>,
  <2.6, -0.8, -3.1>,
  <-0.45, -1.9, -0.7>,
  <5.13, 2.2, 0.91>,
  <0.07, 0.11, -0.23>,
  <-3.7, 4.4, 2.9>,
  <1.01, -0.33, -6.25>,
  <10.5, -20.25, 30.125>,
  <-0.5, -0.5, -0.5>,
  <0.99999, 1e-11, -1e-11>,
  <123.4, 56.7, -89.1> }
// mandel exterior 7, 5
#declare F0 = function { pigment { mandel 30 exterior 7, 5.0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 11)
  #debug concat("V 0.", str(I, 0, 0), " ", str(F0(P_frac[I].x, P_frac[I].y, P_frac[I].z).red, 0, 20), "\n")
#end
// mandel exterior 7, 3.7
#declare F1 = function { pigment { mandel 30 exterior 7, 3.7 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 11)
  #debug concat("V 1.", str(I, 0, 0), " ", str(F1(P_frac[I].x, P_frac[I].y, P_frac[I].z).red, 0, 20), "\n")
#end
// mandel exterior 8, 4
#declare F2 = function { pigment { mandel 30 exterior 8, 4.0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 11)
  #debug concat("V 2.", str(I, 0, 0), " ", str(F2(P_frac[I].x, P_frac[I].y, P_frac[I].z).red, 0, 20), "\n")
#end
// mandel exterior 8, 6.5
#declare F3 = function { pigment { mandel 30 exterior 8, 6.5 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 11)
  #debug concat("V 3.", str(I, 0, 0), " ", str(F3(P_frac[I].x, P_frac[I].y, P_frac[I].z).red, 0, 20), "\n")
#end
// tiling 1
#declare F4 = function { pigment { tiling 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 4.", str(I, 0, 0), " ", str(F4(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 2
#declare F5 = function { pigment { tiling 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 5.", str(I, 0, 0), " ", str(F5(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 3
#declare F6 = function { pigment { tiling 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 6.", str(I, 0, 0), " ", str(F6(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 4
#declare F7 = function { pigment { tiling 4 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 7.", str(I, 0, 0), " ", str(F7(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 5
#declare F8 = function { pigment { tiling 5 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 8.", str(I, 0, 0), " ", str(F8(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 6
#declare F9 = function { pigment { tiling 6 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 9.", str(I, 0, 0), " ", str(F9(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 7
#declare F10 = function { pigment { tiling 7 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 10.", str(I, 0, 0), " ", str(F10(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 8
#declare F11 = function { pigment { tiling 8 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 11.", str(I, 0, 0), " ", str(F11(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 9
#declare F12 = function { pigment { tiling 9 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 12.", str(I, 0, 0), " ", str(F12(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 10
#declare F13 = function { pigment { tiling 10 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 13.", str(I, 0, 0), " ", str(F13(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 11
#declare F14 = function { pigment { tiling 11 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 14.", str(I, 0, 0), " ", str(F14(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 12
#declare F15 = function { pigment { tiling 12 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 15.", str(I, 0, 0), " ", str(F15(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 13
#declare F16 = function { pigment { tiling 13 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 16.", str(I, 0, 0), " ", str(F16(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 14
#declare F17 = function { pigment { tiling 14 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 17.", str(I, 0, 0), " ", str(F17(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 15
#declare F18 = function { pigment { tiling 15 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 18.", str(I, 0, 0), " ", str(F18(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 16
#declare F19 = function { pigment { tiling 16 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 19.", str(I, 0, 0), " ", str(F19(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 17
#declare F20 = function { pigment { tiling 17 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 20.", str(I, 0, 0), " ", str(F20(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 18
#declare F21 = function { pigment { tiling 18 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 21.", str(I, 0, 0), " ", str(F21(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 19
#declare F22 = function { pigment { tiling 19 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 22.", str(I, 0, 0), " ", str(F22(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 20
#declare F23 = function { pigment { tiling 20 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 23.", str(I, 0, 0), " ", str(F23(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 21
#declare F24 = function { pigment { tiling 21 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 24.", str(I, 0, 0), " ", str(F24(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 22
#declare F25 = function { pigment { tiling 22 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 25.", str(I, 0, 0), " ", str(F25(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 23
#declare F26 = function { pigment { tiling 23 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 26.", str(I, 0, 0), " ", str(F26(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 24
#declare F27 = function { pigment { tiling 24 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 27.", str(I, 0, 0), " ", str(F27(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// tiling 25
#declare F28 = function { pigment { tiling 25 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 199)
  #debug concat("V 28.", str(I, 0, 0), " ", str(F28(P_xz200[I].x, P_xz200[I].y, P_xz200[I].z).red, 0, 20), "\n")
#end
// tiling 26
#declare F29 = function { pigment { tiling 26 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 199)
  #debug concat("V 29.", str(I, 0, 0), " ", str(F29(P_xz200[I].x, P_xz200[I].y, P_xz200[I].z).red, 0, 20), "\n")
#end
// tiling 27
#declare F30 = function { pigment { tiling 27 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 199)
  #debug concat("V 30.", str(I, 0, 0), " ", str(F30(P_xz200[I].x, P_xz200[I].y, P_xz200[I].z).red, 0, 20), "\n")
#end
// pavement 3 1 1
#declare F31 = function { pigment { pavement number_of_sides 3 number_of_tiles 1 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 31.", str(I, 0, 0), " ", str(F31(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1
#declare F32 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 32.", str(I, 0, 0), " ", str(F32(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 3 1
#declare F33 = function { pigment { pavement number_of_sides 3 number_of_tiles 3 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 33.", str(I, 0, 0), " ", str(F33(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 4 1
#declare F34 = function { pigment { pavement number_of_sides 3 number_of_tiles 4 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 34.", str(I, 0, 0), " ", str(F34(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 4 2
#declare F35 = function { pigment { pavement number_of_sides 3 number_of_tiles 4 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 35.", str(I, 0, 0), " ", str(F35(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 4 3
#declare F36 = function { pigment { pavement number_of_sides 3 number_of_tiles 4 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 36.", str(I, 0, 0), " ", str(F36(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 5 1
#declare F37 = function { pigment { pavement number_of_sides 3 number_of_tiles 5 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 37.", str(I, 0, 0), " ", str(F37(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 5 2
#declare F38 = function { pigment { pavement number_of_sides 3 number_of_tiles 5 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 38.", str(I, 0, 0), " ", str(F38(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 5 3
#declare F39 = function { pigment { pavement number_of_sides 3 number_of_tiles 5 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 39.", str(I, 0, 0), " ", str(F39(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 5 4
#declare F40 = function { pigment { pavement number_of_sides 3 number_of_tiles 5 pattern 4 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 40.", str(I, 0, 0), " ", str(F40(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 1
#declare F41 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 41.", str(I, 0, 0), " ", str(F41(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 2
#declare F42 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 42.", str(I, 0, 0), " ", str(F42(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 3
#declare F43 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 43.", str(I, 0, 0), " ", str(F43(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4
#declare F44 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 44.", str(I, 0, 0), " ", str(F44(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 5
#declare F45 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 5 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 45.", str(I, 0, 0), " ", str(F45(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 6
#declare F46 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 6 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 46.", str(I, 0, 0), " ", str(F46(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 7
#declare F47 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 7 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 47.", str(I, 0, 0), " ", str(F47(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 8
#declare F48 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 8 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 48.", str(I, 0, 0), " ", str(F48(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 9
#declare F49 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 9 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 49.", str(I, 0, 0), " ", str(F49(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 10
#declare F50 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 10 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 50.", str(I, 0, 0), " ", str(F50(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 11
#declare F51 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 11 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 51.", str(I, 0, 0), " ", str(F51(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12
#declare F52 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 52.", str(I, 0, 0), " ", str(F52(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 1 1
#declare F53 = function { pigment { pavement number_of_sides 4 number_of_tiles 1 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 53.", str(I, 0, 0), " ", str(F53(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 2 1
#declare F54 = function { pigment { pavement number_of_sides 4 number_of_tiles 2 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 54.", str(I, 0, 0), " ", str(F54(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 3 1
#declare F55 = function { pigment { pavement number_of_sides 4 number_of_tiles 3 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 55.", str(I, 0, 0), " ", str(F55(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 3 2
#declare F56 = function { pigment { pavement number_of_sides 4 number_of_tiles 3 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 56.", str(I, 0, 0), " ", str(F56(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 1
#declare F57 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 57.", str(I, 0, 0), " ", str(F57(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 2
#declare F58 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 58.", str(I, 0, 0), " ", str(F58(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 3
#declare F59 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 59.", str(I, 0, 0), " ", str(F59(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 4
#declare F60 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 4 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 60.", str(I, 0, 0), " ", str(F60(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5
#declare F61 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 61.", str(I, 0, 0), " ", str(F61(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 1
#declare F62 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 62.", str(I, 0, 0), " ", str(F62(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 2
#declare F63 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 63.", str(I, 0, 0), " ", str(F63(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 3
#declare F64 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 64.", str(I, 0, 0), " ", str(F64(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 4
#declare F65 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 4 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 65.", str(I, 0, 0), " ", str(F65(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 5
#declare F66 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 5 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 66.", str(I, 0, 0), " ", str(F66(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 6
#declare F67 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 6 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 67.", str(I, 0, 0), " ", str(F67(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7
#declare F68 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 68.", str(I, 0, 0), " ", str(F68(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 8
#declare F69 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 8 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 69.", str(I, 0, 0), " ", str(F69(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 9
#declare F70 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 9 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 70.", str(I, 0, 0), " ", str(F70(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 10
#declare F71 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 10 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 71.", str(I, 0, 0), " ", str(F71(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 11
#declare F72 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 11 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 72.", str(I, 0, 0), " ", str(F72(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 12
#declare F73 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 12 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 73.", str(I, 0, 0), " ", str(F73(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 1
#declare F74 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 74.", str(I, 0, 0), " ", str(F74(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2
#declare F75 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 75.", str(I, 0, 0), " ", str(F75(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 3
#declare F76 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 76.", str(I, 0, 0), " ", str(F76(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 4
#declare F77 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 4 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 77.", str(I, 0, 0), " ", str(F77(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 5
#declare F78 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 5 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 78.", str(I, 0, 0), " ", str(F78(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 6
#declare F79 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 6 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 79.", str(I, 0, 0), " ", str(F79(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 7
#declare F80 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 7 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 80.", str(I, 0, 0), " ", str(F80(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 8
#declare F81 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 8 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 81.", str(I, 0, 0), " ", str(F81(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 9
#declare F82 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 9 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 82.", str(I, 0, 0), " ", str(F82(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 10
#declare F83 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 10 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 83.", str(I, 0, 0), " ", str(F83(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 11
#declare F84 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 11 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 84.", str(I, 0, 0), " ", str(F84(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 12
#declare F85 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 12 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 85.", str(I, 0, 0), " ", str(F85(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 13
#declare F86 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 13 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 86.", str(I, 0, 0), " ", str(F86(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 14
#declare F87 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 14 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 87.", str(I, 0, 0), " ", str(F87(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 15
#declare F88 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 15 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 88.", str(I, 0, 0), " ", str(F88(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 16
#declare F89 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 16 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 89.", str(I, 0, 0), " ", str(F89(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 17
#declare F90 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 17 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 90.", str(I, 0, 0), " ", str(F90(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 18
#declare F91 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 18 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 91.", str(I, 0, 0), " ", str(F91(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 19
#declare F92 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 19 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 92.", str(I, 0, 0), " ", str(F92(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 20
#declare F93 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 20 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 93.", str(I, 0, 0), " ", str(F93(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 21
#declare F94 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 21 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 94.", str(I, 0, 0), " ", str(F94(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 22
#declare F95 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 22 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 95.", str(I, 0, 0), " ", str(F95(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 23
#declare F96 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 23 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 96.", str(I, 0, 0), " ", str(F96(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 24
#declare F97 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 24 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 97.", str(I, 0, 0), " ", str(F97(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 25
#declare F98 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 25 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 98.", str(I, 0, 0), " ", str(F98(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 26
#declare F99 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 26 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 99.", str(I, 0, 0), " ", str(F99(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 27
#declare F100 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 27 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 100.", str(I, 0, 0), " ", str(F100(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 28
#declare F101 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 28 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 101.", str(I, 0, 0), " ", str(F101(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 29
#declare F102 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 29 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 102.", str(I, 0, 0), " ", str(F102(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 30
#declare F103 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 30 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 103.", str(I, 0, 0), " ", str(F103(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 31
#declare F104 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 31 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 104.", str(I, 0, 0), " ", str(F104(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 32
#declare F105 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 32 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 105.", str(I, 0, 0), " ", str(F105(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 33
#declare F106 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 33 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 106.", str(I, 0, 0), " ", str(F106(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 34
#declare F107 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 34 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 107.", str(I, 0, 0), " ", str(F107(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 35
#declare F108 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 35 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 108.", str(I, 0, 0), " ", str(F108(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 1 1
#declare F109 = function { pigment { pavement number_of_sides 6 number_of_tiles 1 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 109.", str(I, 0, 0), " ", str(F109(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 2 1
#declare F110 = function { pigment { pavement number_of_sides 6 number_of_tiles 2 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 110.", str(I, 0, 0), " ", str(F110(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 1
#declare F111 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 111.", str(I, 0, 0), " ", str(F111(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 2
#declare F112 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 112.", str(I, 0, 0), " ", str(F112(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 3
#declare F113 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 113.", str(I, 0, 0), " ", str(F113(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 1
#declare F114 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 114.", str(I, 0, 0), " ", str(F114(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 2
#declare F115 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 115.", str(I, 0, 0), " ", str(F115(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 3
#declare F116 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 116.", str(I, 0, 0), " ", str(F116(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 4
#declare F117 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 4 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 117.", str(I, 0, 0), " ", str(F117(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 5
#declare F118 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 5 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 118.", str(I, 0, 0), " ", str(F118(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 6
#declare F119 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 6 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 119.", str(I, 0, 0), " ", str(F119(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 7
#declare F120 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 7 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 120.", str(I, 0, 0), " ", str(F120(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 1
#declare F121 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 121.", str(I, 0, 0), " ", str(F121(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 2
#declare F122 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 122.", str(I, 0, 0), " ", str(F122(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 3
#declare F123 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 123.", str(I, 0, 0), " ", str(F123(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 4
#declare F124 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 4 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 124.", str(I, 0, 0), " ", str(F124(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 5
#declare F125 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 5 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 125.", str(I, 0, 0), " ", str(F125(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 6
#declare F126 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 6 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 126.", str(I, 0, 0), " ", str(F126(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 7
#declare F127 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 7 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 127.", str(I, 0, 0), " ", str(F127(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 8
#declare F128 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 8 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 128.", str(I, 0, 0), " ", str(F128(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 9
#declare F129 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 9 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 129.", str(I, 0, 0), " ", str(F129(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 10
#declare F130 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 10 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 130.", str(I, 0, 0), " ", str(F130(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 11
#declare F131 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 11 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 131.", str(I, 0, 0), " ", str(F131(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 12
#declare F132 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 12 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 132.", str(I, 0, 0), " ", str(F132(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 13
#declare F133 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 13 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 133.", str(I, 0, 0), " ", str(F133(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 14
#declare F134 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 14 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 134.", str(I, 0, 0), " ", str(F134(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 15
#declare F135 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 15 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 135.", str(I, 0, 0), " ", str(F135(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 16
#declare F136 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 16 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 136.", str(I, 0, 0), " ", str(F136(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 17
#declare F137 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 17 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 137.", str(I, 0, 0), " ", str(F137(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 18
#declare F138 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 18 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 138.", str(I, 0, 0), " ", str(F138(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 19
#declare F139 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 19 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 139.", str(I, 0, 0), " ", str(F139(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 20
#declare F140 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 20 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 140.", str(I, 0, 0), " ", str(F140(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 21
#declare F141 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 21 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 141.", str(I, 0, 0), " ", str(F141(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 22
#declare F142 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 22 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 39)
  #debug concat("V 142.", str(I, 0, 0), " ", str(F142(P_xz[I].x, P_xz[I].y, P_xz[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 0 interior 0 exterior 1
#declare F143 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 0 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 143.", str(I, 0, 0), " ", str(F143(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 0 interior 0 exterior 2
#declare F144 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 0 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 144.", str(I, 0, 0), " ", str(F144(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 0 interior 1 exterior 0
#declare F145 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 0 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 145.", str(I, 0, 0), " ", str(F145(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 0 interior 1 exterior 1
#declare F146 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 0 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 146.", str(I, 0, 0), " ", str(F146(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 0 interior 1 exterior 2
#declare F147 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 0 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 147.", str(I, 0, 0), " ", str(F147(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 0 interior 2 exterior 0
#declare F148 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 0 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 148.", str(I, 0, 0), " ", str(F148(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 0 interior 2 exterior 1
#declare F149 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 0 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 149.", str(I, 0, 0), " ", str(F149(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 0 interior 2 exterior 2
#declare F150 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 0 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 150.", str(I, 0, 0), " ", str(F150(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 1 interior 0 exterior 0
#declare F151 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 1 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 151.", str(I, 0, 0), " ", str(F151(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 1 interior 0 exterior 1
#declare F152 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 1 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 152.", str(I, 0, 0), " ", str(F152(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 1 interior 0 exterior 2
#declare F153 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 1 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 153.", str(I, 0, 0), " ", str(F153(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 1 interior 1 exterior 0
#declare F154 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 1 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 154.", str(I, 0, 0), " ", str(F154(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 1 interior 1 exterior 1
#declare F155 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 1 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 155.", str(I, 0, 0), " ", str(F155(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 1 interior 1 exterior 2
#declare F156 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 1 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 156.", str(I, 0, 0), " ", str(F156(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 1 interior 2 exterior 0
#declare F157 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 1 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 157.", str(I, 0, 0), " ", str(F157(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 1 interior 2 exterior 1
#declare F158 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 1 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 158.", str(I, 0, 0), " ", str(F158(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 1 interior 2 exterior 2
#declare F159 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 1 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 159.", str(I, 0, 0), " ", str(F159(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 2 interior 0 exterior 0
#declare F160 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 2 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 160.", str(I, 0, 0), " ", str(F160(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 2 interior 0 exterior 1
#declare F161 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 2 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 161.", str(I, 0, 0), " ", str(F161(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 2 interior 0 exterior 2
#declare F162 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 2 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 162.", str(I, 0, 0), " ", str(F162(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 2 interior 1 exterior 0
#declare F163 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 2 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 163.", str(I, 0, 0), " ", str(F163(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 2 interior 1 exterior 1
#declare F164 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 2 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 164.", str(I, 0, 0), " ", str(F164(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 2 interior 1 exterior 2
#declare F165 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 2 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 165.", str(I, 0, 0), " ", str(F165(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 2 interior 2 exterior 0
#declare F166 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 2 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 166.", str(I, 0, 0), " ", str(F166(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 2 interior 2 exterior 1
#declare F167 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 2 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 167.", str(I, 0, 0), " ", str(F167(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 2 interior 2 exterior 2
#declare F168 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 2 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 168.", str(I, 0, 0), " ", str(F168(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 3 interior 0 exterior 0
#declare F169 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 3 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 169.", str(I, 0, 0), " ", str(F169(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 3 interior 0 exterior 1
#declare F170 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 3 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 170.", str(I, 0, 0), " ", str(F170(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 3 interior 0 exterior 2
#declare F171 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 3 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 171.", str(I, 0, 0), " ", str(F171(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 3 interior 1 exterior 0
#declare F172 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 3 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 172.", str(I, 0, 0), " ", str(F172(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 3 interior 1 exterior 1
#declare F173 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 3 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 173.", str(I, 0, 0), " ", str(F173(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 3 interior 1 exterior 2
#declare F174 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 3 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 174.", str(I, 0, 0), " ", str(F174(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 3 interior 2 exterior 0
#declare F175 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 3 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 175.", str(I, 0, 0), " ", str(F175(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 3 interior 2 exterior 1
#declare F176 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 3 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 176.", str(I, 0, 0), " ", str(F176(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 6 2 form 3 interior 2 exterior 2
#declare F177 = function { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 2 form 3 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 177.", str(I, 0, 0), " ", str(F177(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 0 interior 0 exterior 1
#declare F178 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 0 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 178.", str(I, 0, 0), " ", str(F178(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 0 interior 0 exterior 2
#declare F179 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 0 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 179.", str(I, 0, 0), " ", str(F179(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 0 interior 1 exterior 0
#declare F180 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 0 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 180.", str(I, 0, 0), " ", str(F180(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 0 interior 1 exterior 1
#declare F181 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 0 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 181.", str(I, 0, 0), " ", str(F181(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 0 interior 1 exterior 2
#declare F182 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 0 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 182.", str(I, 0, 0), " ", str(F182(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 0 interior 2 exterior 0
#declare F183 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 0 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 183.", str(I, 0, 0), " ", str(F183(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 0 interior 2 exterior 1
#declare F184 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 0 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 184.", str(I, 0, 0), " ", str(F184(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 0 interior 2 exterior 2
#declare F185 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 0 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 185.", str(I, 0, 0), " ", str(F185(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 1 interior 0 exterior 0
#declare F186 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 1 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 186.", str(I, 0, 0), " ", str(F186(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 1 interior 0 exterior 1
#declare F187 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 1 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 187.", str(I, 0, 0), " ", str(F187(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 1 interior 0 exterior 2
#declare F188 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 1 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 188.", str(I, 0, 0), " ", str(F188(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 1 interior 1 exterior 0
#declare F189 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 1 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 189.", str(I, 0, 0), " ", str(F189(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 1 interior 1 exterior 1
#declare F190 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 1 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 190.", str(I, 0, 0), " ", str(F190(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 1 interior 1 exterior 2
#declare F191 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 1 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 191.", str(I, 0, 0), " ", str(F191(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 1 interior 2 exterior 0
#declare F192 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 1 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 192.", str(I, 0, 0), " ", str(F192(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 1 interior 2 exterior 1
#declare F193 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 1 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 193.", str(I, 0, 0), " ", str(F193(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 1 interior 2 exterior 2
#declare F194 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 1 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 194.", str(I, 0, 0), " ", str(F194(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 2 interior 0 exterior 0
#declare F195 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 195.", str(I, 0, 0), " ", str(F195(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 2 interior 0 exterior 1
#declare F196 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 196.", str(I, 0, 0), " ", str(F196(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 2 interior 0 exterior 2
#declare F197 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 197.", str(I, 0, 0), " ", str(F197(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 2 interior 1 exterior 0
#declare F198 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 198.", str(I, 0, 0), " ", str(F198(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 2 interior 1 exterior 1
#declare F199 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 199.", str(I, 0, 0), " ", str(F199(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 2 interior 1 exterior 2
#declare F200 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 200.", str(I, 0, 0), " ", str(F200(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 2 interior 2 exterior 0
#declare F201 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 201.", str(I, 0, 0), " ", str(F201(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 2 interior 2 exterior 1
#declare F202 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 202.", str(I, 0, 0), " ", str(F202(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 2 interior 2 exterior 2
#declare F203 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 203.", str(I, 0, 0), " ", str(F203(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 3 interior 0 exterior 0
#declare F204 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 3 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 204.", str(I, 0, 0), " ", str(F204(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 3 interior 0 exterior 1
#declare F205 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 3 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 205.", str(I, 0, 0), " ", str(F205(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 3 interior 0 exterior 2
#declare F206 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 3 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 206.", str(I, 0, 0), " ", str(F206(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 3 interior 1 exterior 0
#declare F207 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 3 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 207.", str(I, 0, 0), " ", str(F207(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 3 interior 1 exterior 1
#declare F208 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 3 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 208.", str(I, 0, 0), " ", str(F208(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 3 interior 1 exterior 2
#declare F209 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 3 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 209.", str(I, 0, 0), " ", str(F209(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 3 interior 2 exterior 0
#declare F210 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 3 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 210.", str(I, 0, 0), " ", str(F210(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 3 interior 2 exterior 1
#declare F211 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 3 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 211.", str(I, 0, 0), " ", str(F211(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 4 5 form 3 interior 2 exterior 2
#declare F212 = function { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 3 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 212.", str(I, 0, 0), " ", str(F212(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 0 interior 0 exterior 1
#declare F213 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 0 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 213.", str(I, 0, 0), " ", str(F213(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 0 interior 0 exterior 2
#declare F214 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 0 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 214.", str(I, 0, 0), " ", str(F214(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 0 interior 1 exterior 0
#declare F215 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 0 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 215.", str(I, 0, 0), " ", str(F215(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 0 interior 1 exterior 1
#declare F216 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 0 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 216.", str(I, 0, 0), " ", str(F216(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 0 interior 1 exterior 2
#declare F217 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 0 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 217.", str(I, 0, 0), " ", str(F217(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 0 interior 2 exterior 0
#declare F218 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 0 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 218.", str(I, 0, 0), " ", str(F218(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 0 interior 2 exterior 1
#declare F219 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 0 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 219.", str(I, 0, 0), " ", str(F219(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 0 interior 2 exterior 2
#declare F220 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 0 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 220.", str(I, 0, 0), " ", str(F220(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 1 interior 0 exterior 0
#declare F221 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 1 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 221.", str(I, 0, 0), " ", str(F221(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 1 interior 0 exterior 1
#declare F222 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 1 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 222.", str(I, 0, 0), " ", str(F222(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 1 interior 0 exterior 2
#declare F223 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 1 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 223.", str(I, 0, 0), " ", str(F223(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 1 interior 1 exterior 0
#declare F224 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 1 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 224.", str(I, 0, 0), " ", str(F224(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 1 interior 1 exterior 1
#declare F225 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 1 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 225.", str(I, 0, 0), " ", str(F225(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 1 interior 1 exterior 2
#declare F226 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 1 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 226.", str(I, 0, 0), " ", str(F226(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 1 interior 2 exterior 0
#declare F227 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 1 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 227.", str(I, 0, 0), " ", str(F227(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 1 interior 2 exterior 1
#declare F228 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 1 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 228.", str(I, 0, 0), " ", str(F228(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 1 interior 2 exterior 2
#declare F229 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 1 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 229.", str(I, 0, 0), " ", str(F229(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 2 interior 0 exterior 0
#declare F230 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 2 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 230.", str(I, 0, 0), " ", str(F230(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 2 interior 0 exterior 1
#declare F231 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 2 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 231.", str(I, 0, 0), " ", str(F231(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 2 interior 0 exterior 2
#declare F232 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 2 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 232.", str(I, 0, 0), " ", str(F232(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 2 interior 1 exterior 0
#declare F233 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 2 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 233.", str(I, 0, 0), " ", str(F233(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 2 interior 1 exterior 1
#declare F234 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 2 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 234.", str(I, 0, 0), " ", str(F234(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 2 interior 1 exterior 2
#declare F235 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 2 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 235.", str(I, 0, 0), " ", str(F235(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 2 interior 2 exterior 0
#declare F236 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 2 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 236.", str(I, 0, 0), " ", str(F236(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 2 interior 2 exterior 1
#declare F237 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 2 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 237.", str(I, 0, 0), " ", str(F237(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 2 interior 2 exterior 2
#declare F238 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 2 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 238.", str(I, 0, 0), " ", str(F238(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 3 interior 0 exterior 0
#declare F239 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 3 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 239.", str(I, 0, 0), " ", str(F239(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 3 interior 0 exterior 1
#declare F240 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 3 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 240.", str(I, 0, 0), " ", str(F240(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 3 interior 0 exterior 2
#declare F241 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 3 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 241.", str(I, 0, 0), " ", str(F241(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 3 interior 1 exterior 0
#declare F242 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 3 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 242.", str(I, 0, 0), " ", str(F242(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 3 interior 1 exterior 1
#declare F243 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 3 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 243.", str(I, 0, 0), " ", str(F243(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 3 interior 1 exterior 2
#declare F244 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 3 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 244.", str(I, 0, 0), " ", str(F244(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 3 interior 2 exterior 0
#declare F245 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 3 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 245.", str(I, 0, 0), " ", str(F245(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 3 interior 2 exterior 1
#declare F246 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 3 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 246.", str(I, 0, 0), " ", str(F246(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 4 5 7 form 3 interior 2 exterior 2
#declare F247 = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 form 3 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 247.", str(I, 0, 0), " ", str(F247(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 0 interior 0 exterior 1
#declare F248 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 0 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 248.", str(I, 0, 0), " ", str(F248(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 0 interior 0 exterior 2
#declare F249 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 0 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 249.", str(I, 0, 0), " ", str(F249(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 0 interior 1 exterior 0
#declare F250 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 0 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 250.", str(I, 0, 0), " ", str(F250(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 0 interior 1 exterior 1
#declare F251 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 0 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 251.", str(I, 0, 0), " ", str(F251(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 0 interior 1 exterior 2
#declare F252 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 0 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 252.", str(I, 0, 0), " ", str(F252(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 0 interior 2 exterior 0
#declare F253 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 0 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 253.", str(I, 0, 0), " ", str(F253(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 0 interior 2 exterior 1
#declare F254 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 0 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 254.", str(I, 0, 0), " ", str(F254(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 0 interior 2 exterior 2
#declare F255 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 0 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 255.", str(I, 0, 0), " ", str(F255(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 1 interior 0 exterior 0
#declare F256 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 1 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 256.", str(I, 0, 0), " ", str(F256(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 1 interior 0 exterior 1
#declare F257 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 1 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 257.", str(I, 0, 0), " ", str(F257(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 1 interior 0 exterior 2
#declare F258 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 1 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 258.", str(I, 0, 0), " ", str(F258(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 1 interior 1 exterior 0
#declare F259 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 1 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 259.", str(I, 0, 0), " ", str(F259(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 1 interior 1 exterior 1
#declare F260 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 1 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 260.", str(I, 0, 0), " ", str(F260(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 1 interior 1 exterior 2
#declare F261 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 1 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 261.", str(I, 0, 0), " ", str(F261(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 1 interior 2 exterior 0
#declare F262 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 1 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 262.", str(I, 0, 0), " ", str(F262(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 1 interior 2 exterior 1
#declare F263 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 1 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 263.", str(I, 0, 0), " ", str(F263(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 1 interior 2 exterior 2
#declare F264 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 1 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 264.", str(I, 0, 0), " ", str(F264(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 2 interior 0 exterior 0
#declare F265 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 265.", str(I, 0, 0), " ", str(F265(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 2 interior 0 exterior 1
#declare F266 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 266.", str(I, 0, 0), " ", str(F266(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 2 interior 0 exterior 2
#declare F267 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 267.", str(I, 0, 0), " ", str(F267(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 2 interior 1 exterior 0
#declare F268 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 268.", str(I, 0, 0), " ", str(F268(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 2 interior 1 exterior 1
#declare F269 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 269.", str(I, 0, 0), " ", str(F269(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 2 interior 1 exterior 2
#declare F270 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 270.", str(I, 0, 0), " ", str(F270(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 2 interior 2 exterior 0
#declare F271 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 271.", str(I, 0, 0), " ", str(F271(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 2 interior 2 exterior 1
#declare F272 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 272.", str(I, 0, 0), " ", str(F272(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 12 form 2 interior 2 exterior 2
#declare F273 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 2 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 273.", str(I, 0, 0), " ", str(F273(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 0 interior 0 exterior 1
#declare F274 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 0 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 274.", str(I, 0, 0), " ", str(F274(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 0 interior 0 exterior 2
#declare F275 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 0 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 275.", str(I, 0, 0), " ", str(F275(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 0 interior 1 exterior 0
#declare F276 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 0 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 276.", str(I, 0, 0), " ", str(F276(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 0 interior 1 exterior 1
#declare F277 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 0 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 277.", str(I, 0, 0), " ", str(F277(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 0 interior 1 exterior 2
#declare F278 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 0 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 278.", str(I, 0, 0), " ", str(F278(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 0 interior 2 exterior 0
#declare F279 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 0 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 279.", str(I, 0, 0), " ", str(F279(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 0 interior 2 exterior 1
#declare F280 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 0 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 280.", str(I, 0, 0), " ", str(F280(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 0 interior 2 exterior 2
#declare F281 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 0 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 281.", str(I, 0, 0), " ", str(F281(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 1 interior 0 exterior 0
#declare F282 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 282.", str(I, 0, 0), " ", str(F282(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 1 interior 0 exterior 1
#declare F283 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 283.", str(I, 0, 0), " ", str(F283(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 1 interior 0 exterior 2
#declare F284 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 284.", str(I, 0, 0), " ", str(F284(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 1 interior 1 exterior 0
#declare F285 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 285.", str(I, 0, 0), " ", str(F285(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 1 interior 1 exterior 1
#declare F286 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 286.", str(I, 0, 0), " ", str(F286(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 1 interior 1 exterior 2
#declare F287 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 287.", str(I, 0, 0), " ", str(F287(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 1 interior 2 exterior 0
#declare F288 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 288.", str(I, 0, 0), " ", str(F288(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 1 interior 2 exterior 1
#declare F289 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 289.", str(I, 0, 0), " ", str(F289(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 1 interior 2 exterior 2
#declare F290 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 290.", str(I, 0, 0), " ", str(F290(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 2 interior 0 exterior 0
#declare F291 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 2 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 291.", str(I, 0, 0), " ", str(F291(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 2 interior 0 exterior 1
#declare F292 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 2 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 292.", str(I, 0, 0), " ", str(F292(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 2 interior 0 exterior 2
#declare F293 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 2 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 293.", str(I, 0, 0), " ", str(F293(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 2 interior 1 exterior 0
#declare F294 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 2 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 294.", str(I, 0, 0), " ", str(F294(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 2 interior 1 exterior 1
#declare F295 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 2 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 295.", str(I, 0, 0), " ", str(F295(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 2 interior 1 exterior 2
#declare F296 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 2 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 296.", str(I, 0, 0), " ", str(F296(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 2 interior 2 exterior 0
#declare F297 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 2 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 297.", str(I, 0, 0), " ", str(F297(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 2 interior 2 exterior 1
#declare F298 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 2 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 298.", str(I, 0, 0), " ", str(F298(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 6 4 form 2 interior 2 exterior 2
#declare F299 = function { pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 2 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 299.", str(I, 0, 0), " ", str(F299(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 0 interior 0 exterior 1
#declare F300 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 0 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 300.", str(I, 0, 0), " ", str(F300(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 0 interior 0 exterior 2
#declare F301 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 0 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 301.", str(I, 0, 0), " ", str(F301(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 0 interior 1 exterior 0
#declare F302 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 0 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 302.", str(I, 0, 0), " ", str(F302(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 0 interior 1 exterior 1
#declare F303 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 0 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 303.", str(I, 0, 0), " ", str(F303(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 0 interior 1 exterior 2
#declare F304 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 0 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 304.", str(I, 0, 0), " ", str(F304(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 0 interior 2 exterior 0
#declare F305 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 0 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 305.", str(I, 0, 0), " ", str(F305(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 0 interior 2 exterior 1
#declare F306 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 0 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 306.", str(I, 0, 0), " ", str(F306(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 0 interior 2 exterior 2
#declare F307 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 0 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 307.", str(I, 0, 0), " ", str(F307(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 1 interior 0 exterior 0
#declare F308 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 308.", str(I, 0, 0), " ", str(F308(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 1 interior 0 exterior 1
#declare F309 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 309.", str(I, 0, 0), " ", str(F309(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 1 interior 0 exterior 2
#declare F310 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 310.", str(I, 0, 0), " ", str(F310(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 1 interior 1 exterior 0
#declare F311 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 311.", str(I, 0, 0), " ", str(F311(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 1 interior 1 exterior 1
#declare F312 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 312.", str(I, 0, 0), " ", str(F312(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 1 interior 1 exterior 2
#declare F313 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 313.", str(I, 0, 0), " ", str(F313(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 1 interior 2 exterior 0
#declare F314 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 314.", str(I, 0, 0), " ", str(F314(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 1 interior 2 exterior 1
#declare F315 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 315.", str(I, 0, 0), " ", str(F315(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 1 interior 2 exterior 2
#declare F316 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 316.", str(I, 0, 0), " ", str(F316(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 2 interior 0 exterior 0
#declare F317 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 2 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 317.", str(I, 0, 0), " ", str(F317(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 2 interior 0 exterior 1
#declare F318 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 2 interior 0 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 318.", str(I, 0, 0), " ", str(F318(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 2 interior 0 exterior 2
#declare F319 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 2 interior 0 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 319.", str(I, 0, 0), " ", str(F319(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 2 interior 1 exterior 0
#declare F320 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 2 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 320.", str(I, 0, 0), " ", str(F320(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 2 interior 1 exterior 1
#declare F321 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 2 interior 1 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 321.", str(I, 0, 0), " ", str(F321(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 2 interior 1 exterior 2
#declare F322 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 2 interior 1 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 322.", str(I, 0, 0), " ", str(F322(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 2 interior 2 exterior 0
#declare F323 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 2 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 323.", str(I, 0, 0), " ", str(F323(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 2 interior 2 exterior 1
#declare F324 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 2 interior 2 exterior 1 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 324.", str(I, 0, 0), " ", str(F324(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 3 2 1 form 2 interior 2 exterior 2
#declare F325 = function { pigment { pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 2 interior 2 exterior 2 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 325.", str(I, 0, 0), " ", str(F325(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 2 form 0 interior 1 exterior 0
#declare F326 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 form 0 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 326.", str(I, 0, 0), " ", str(F326(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 2 form 0 interior 2 exterior 0
#declare F327 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 form 0 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 327.", str(I, 0, 0), " ", str(F327(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 2 form 1 interior 0 exterior 0
#declare F328 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 form 1 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 328.", str(I, 0, 0), " ", str(F328(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 2 form 1 interior 1 exterior 0
#declare F329 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 form 1 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 329.", str(I, 0, 0), " ", str(F329(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 2 form 1 interior 2 exterior 0
#declare F330 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 form 1 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 330.", str(I, 0, 0), " ", str(F330(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 2 form 2 interior 0 exterior 0
#declare F331 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 form 2 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 331.", str(I, 0, 0), " ", str(F331(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 2 form 2 interior 1 exterior 0
#declare F332 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 form 2 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 332.", str(I, 0, 0), " ", str(F332(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 4 2 form 2 interior 2 exterior 0
#declare F333 = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 2 form 2 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 333.", str(I, 0, 0), " ", str(F333(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 9 form 0 interior 1 exterior 0
#declare F334 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 9 form 0 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 334.", str(I, 0, 0), " ", str(F334(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 9 form 0 interior 2 exterior 0
#declare F335 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 9 form 0 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 335.", str(I, 0, 0), " ", str(F335(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 9 form 1 interior 0 exterior 0
#declare F336 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 9 form 1 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 336.", str(I, 0, 0), " ", str(F336(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 9 form 1 interior 1 exterior 0
#declare F337 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 9 form 1 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 337.", str(I, 0, 0), " ", str(F337(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 9 form 1 interior 2 exterior 0
#declare F338 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 9 form 1 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 338.", str(I, 0, 0), " ", str(F338(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 9 form 2 interior 0 exterior 0
#declare F339 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 9 form 2 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 339.", str(I, 0, 0), " ", str(F339(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 9 form 2 interior 1 exterior 0
#declare F340 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 9 form 2 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 340.", str(I, 0, 0), " ", str(F340(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 5 9 form 2 interior 2 exterior 0
#declare F341 = function { pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 9 form 2 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 341.", str(I, 0, 0), " ", str(F341(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 3 form 0 interior 1 exterior 0
#declare F342 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 0 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 342.", str(I, 0, 0), " ", str(F342(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 3 form 0 interior 2 exterior 0
#declare F343 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 0 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 343.", str(I, 0, 0), " ", str(F343(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 3 form 1 interior 0 exterior 0
#declare F344 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 1 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 344.", str(I, 0, 0), " ", str(F344(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 3 form 1 interior 1 exterior 0
#declare F345 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 1 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 345.", str(I, 0, 0), " ", str(F345(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 3 form 1 interior 2 exterior 0
#declare F346 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 1 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 346.", str(I, 0, 0), " ", str(F346(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 3 form 2 interior 0 exterior 0
#declare F347 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 2 interior 0 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 347.", str(I, 0, 0), " ", str(F347(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 3 form 2 interior 1 exterior 0
#declare F348 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 2 interior 1 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 348.", str(I, 0, 0), " ", str(F348(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
// pavement 6 3 3 form 2 interior 2 exterior 0
#declare F349 = function { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 2 interior 2 exterior 0 color_map { [0 rgb 0] [1 rgb 1] } } }
#for (I, 0, 23)
  #debug concat("V 349.", str(I, 0, 0), " ", str(F349(P_xz24[I].x, P_xz24[I].y, P_xz24[I].z).red, 0, 20), "\n")
#end
