// Written by gen.py (beside it); run: povray +Ipattern_values.pov +O/tmp/t.png +W8 +H6 -D  (values go to #debug)
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
// cubic
#declare F0 = function { pattern { cubic frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 0.", str(I, 0, 0), " ", str(F0(P_cubic[I].x, P_cubic[I].y, P_cubic[I].z), 0, 20), "\n")
#end
// leopard
#declare F1 = function { pattern { leopard frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 1.", str(I, 0, 0), " ", str(F1(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// onion
#declare F2 = function { pattern { onion frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 2.", str(I, 0, 0), " ", str(F2(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// radial
#declare F3 = function { pattern { radial frequency 0 } }
#for (I, 0, 10)
  #debug concat("V 3.", str(I, 0, 0), " ", str(F3(P_near_axis[I].x, P_near_axis[I].y, P_near_axis[I].z), 0, 20), "\n")
#end
// planar
#declare F4 = function { pattern { planar frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 4.", str(I, 0, 0), " ", str(F4(P_g3_planar[I].x, P_g3_planar[I].y, P_g3_planar[I].z), 0, 20), "\n")
#end
// boxed
#declare F5 = function { pattern { boxed frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 5.", str(I, 0, 0), " ", str(F5(P_g3_more[I].x, P_g3_more[I].y, P_g3_more[I].z), 0, 20), "\n")
#end
// spherical
#declare F6 = function { pattern { spherical frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 6.", str(I, 0, 0), " ", str(F6(P_g3_more[I].x, P_g3_more[I].y, P_g3_more[I].z), 0, 20), "\n")
#end
// cylindrical
#declare F7 = function { pattern { cylindrical frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 7.", str(I, 0, 0), " ", str(F7(P_g3_more[I].x, P_g3_more[I].y, P_g3_more[I].z), 0, 20), "\n")
#end
// quilted
#declare F8 = function { pattern { quilted frequency 0 } }
#for (I, 0, 8)
  #debug concat("V 8.", str(I, 0, 0), " ", str(F8(P_g3_quilt[I].x, P_g3_quilt[I].y, P_g3_quilt[I].z), 0, 20), "\n")
#end
// quilted 0.3 2.5
#declare F9 = function { pattern { quilted control0 0.3 control1 2.5 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 9.", str(I, 0, 0), " ", str(F9(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// spiral1 5
#declare F10 = function { pattern { spiral1 5 frequency 0 ramp_wave } }
#for (I, 0, 8)
  #debug concat("V 10.", str(I, 0, 0), " ", str(F10(P_g3_axis[I].x, P_g3_axis[I].y, P_g3_axis[I].z), 0, 20), "\n")
#end
// spiral2 3
#declare F11 = function { pattern { spiral2 3 frequency 0 ramp_wave } }
#for (I, 0, 8)
  #debug concat("V 11.", str(I, 0, 0), " ", str(F11(P_g3_axis[I].x, P_g3_axis[I].y, P_g3_axis[I].z), 0, 20), "\n")
#end
// marble
#declare F12 = function { pattern { marble frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 12.", str(I, 0, 0), " ", str(F12(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// wood
#declare F13 = function { pattern { wood frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 13.", str(I, 0, 0), " ", str(F13(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// mandel exponent 2
#declare F14 = function { pattern { mandel 30 exponent 2 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 14.", str(I, 0, 0), " ", str(F14(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 3
#declare F15 = function { pattern { mandel 30 exponent 3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 15.", str(I, 0, 0), " ", str(F15(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 4
#declare F16 = function { pattern { mandel 30 exponent 4 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 16.", str(I, 0, 0), " ", str(F16(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 5
#declare F17 = function { pattern { mandel 30 exponent 5 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 17.", str(I, 0, 0), " ", str(F17(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 8
#declare F18 = function { pattern { mandel 30 exponent 8 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 18.", str(I, 0, 0), " ", str(F18(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 2
#declare F19 = function { pattern { julia <0.353, 0.288>, 40 exponent 2 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 19.", str(I, 0, 0), " ", str(F19(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 3
#declare F20 = function { pattern { julia <0.353, 0.288>, 40 exponent 3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 20.", str(I, 0, 0), " ", str(F20(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 4
#declare F21 = function { pattern { julia <0.353, 0.288>, 40 exponent 4 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 21.", str(I, 0, 0), " ", str(F21(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 6
#declare F22 = function { pattern { julia <0.353, 0.288>, 40 exponent 6 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 22.", str(I, 0, 0), " ", str(F22(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 1 (as 2)
#declare F23 = function { pattern { mandel 25 exponent 1 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 23.", str(I, 0, 0), " ", str(F23(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 40 (as 2)
#declare F24 = function { pattern { mandel 25 exponent 40 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 24.", str(I, 0, 0), " ", str(F24(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel interior 0
#declare F25 = function { pattern { mandel 30 interior 0, 1.3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 25.", str(I, 0, 0), " ", str(F25(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 3 interior 0
#declare F26 = function { pattern { julia <-0.2, 0.6>, 20 exponent 3 interior 0, 0.8 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 26.", str(I, 0, 0), " ", str(F26(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel interior 1
#declare F27 = function { pattern { mandel 30 interior 1, 1.3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 27.", str(I, 0, 0), " ", str(F27(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 3 interior 1
#declare F28 = function { pattern { julia <-0.2, 0.6>, 20 exponent 3 interior 1, 0.8 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 28.", str(I, 0, 0), " ", str(F28(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel interior 2
#declare F29 = function { pattern { mandel 30 interior 2, 1.3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 29.", str(I, 0, 0), " ", str(F29(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 3 interior 2
#declare F30 = function { pattern { julia <-0.2, 0.6>, 20 exponent 3 interior 2, 0.8 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 30.", str(I, 0, 0), " ", str(F30(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel interior 3
#declare F31 = function { pattern { mandel 30 interior 3, 1.3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 31.", str(I, 0, 0), " ", str(F31(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 3 interior 3
#declare F32 = function { pattern { julia <-0.2, 0.6>, 20 exponent 3 interior 3, 0.8 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 32.", str(I, 0, 0), " ", str(F32(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel interior 4
#declare F33 = function { pattern { mandel 30 interior 4, 1.3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 33.", str(I, 0, 0), " ", str(F33(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 3 interior 4
#declare F34 = function { pattern { julia <-0.2, 0.6>, 20 exponent 3 interior 4, 0.8 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 34.", str(I, 0, 0), " ", str(F34(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel interior 5
#declare F35 = function { pattern { mandel 30 interior 5, 1.3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 35.", str(I, 0, 0), " ", str(F35(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 3 interior 5
#declare F36 = function { pattern { julia <-0.2, 0.6>, 20 exponent 3 interior 5, 0.8 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 36.", str(I, 0, 0), " ", str(F36(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel interior 6
#declare F37 = function { pattern { mandel 30 interior 6, 1.3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 37.", str(I, 0, 0), " ", str(F37(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// julia exponent 3 interior 6
#declare F38 = function { pattern { julia <-0.2, 0.6>, 20 exponent 3 interior 6, 0.8 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 38.", str(I, 0, 0), " ", str(F38(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exterior 0
#declare F39 = function { pattern { mandel 30 exterior 0, 0.7 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 39.", str(I, 0, 0), " ", str(F39(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 7 exterior 0
#declare F40 = function { pattern { mandel 15 exponent 7 exterior 0, 2.5 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 40.", str(I, 0, 0), " ", str(F40(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exterior 1
#declare F41 = function { pattern { mandel 30 exterior 1, 0.7 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 41.", str(I, 0, 0), " ", str(F41(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 7 exterior 1
#declare F42 = function { pattern { mandel 15 exponent 7 exterior 1, 2.5 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 42.", str(I, 0, 0), " ", str(F42(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exterior 2
#declare F43 = function { pattern { mandel 30 exterior 2, 0.7 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 43.", str(I, 0, 0), " ", str(F43(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 7 exterior 2
#declare F44 = function { pattern { mandel 15 exponent 7 exterior 2, 2.5 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 44.", str(I, 0, 0), " ", str(F44(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exterior 3
#declare F45 = function { pattern { mandel 30 exterior 3, 0.7 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 45.", str(I, 0, 0), " ", str(F45(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 7 exterior 3
#declare F46 = function { pattern { mandel 15 exponent 7 exterior 3, 2.5 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 46.", str(I, 0, 0), " ", str(F46(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exterior 4
#declare F47 = function { pattern { mandel 30 exterior 4, 0.7 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 47.", str(I, 0, 0), " ", str(F47(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 7 exterior 4
#declare F48 = function { pattern { mandel 15 exponent 7 exterior 4, 2.5 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 48.", str(I, 0, 0), " ", str(F48(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exterior 5
#declare F49 = function { pattern { mandel 30 exterior 5, 0.7 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 49.", str(I, 0, 0), " ", str(F49(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 7 exterior 5
#declare F50 = function { pattern { mandel 15 exponent 7 exterior 5, 2.5 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 50.", str(I, 0, 0), " ", str(F50(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exterior 6
#declare F51 = function { pattern { mandel 30 exterior 6, 0.7 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 51.", str(I, 0, 0), " ", str(F51(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// mandel exponent 7 exterior 6
#declare F52 = function { pattern { mandel 15 exponent 7 exterior 6, 2.5 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 52.", str(I, 0, 0), " ", str(F52(P_frac[I].x, P_frac[I].y, P_frac[I].z), 0, 20), "\n")
#end
// magnet 1 mandel interior 0 exterior 1
#declare F53 = function { pattern { magnet 1 mandel 20 interior 0, 1.5 exterior 1, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 53.", str(I, 0, 0), " ", str(F53(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 1 julia interior 0 exterior 1
#declare F54 = function { pattern { magnet 1 julia <0.4, -0.2>, 20 interior 0, 1.5 exterior 1, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 54.", str(I, 0, 0), " ", str(F54(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 1 mandel interior 1 exterior 2
#declare F55 = function { pattern { magnet 1 mandel 20 interior 1, 1.5 exterior 2, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 55.", str(I, 0, 0), " ", str(F55(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 1 julia interior 1 exterior 2
#declare F56 = function { pattern { magnet 1 julia <0.4, -0.2>, 20 interior 1, 1.5 exterior 2, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 56.", str(I, 0, 0), " ", str(F56(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 1 mandel interior 4 exterior 6
#declare F57 = function { pattern { magnet 1 mandel 20 interior 4, 1.5 exterior 6, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 57.", str(I, 0, 0), " ", str(F57(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 1 julia interior 4 exterior 6
#declare F58 = function { pattern { magnet 1 julia <0.4, -0.2>, 20 interior 4, 1.5 exterior 6, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 58.", str(I, 0, 0), " ", str(F58(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 1 mandel interior 6 exterior 3
#declare F59 = function { pattern { magnet 1 mandel 20 interior 6, 1.5 exterior 3, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 59.", str(I, 0, 0), " ", str(F59(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 1 julia interior 6 exterior 3
#declare F60 = function { pattern { magnet 1 julia <0.4, -0.2>, 20 interior 6, 1.5 exterior 3, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 60.", str(I, 0, 0), " ", str(F60(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 2 mandel interior 0 exterior 1
#declare F61 = function { pattern { magnet 2 mandel 20 interior 0, 1.5 exterior 1, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 61.", str(I, 0, 0), " ", str(F61(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 2 julia interior 0 exterior 1
#declare F62 = function { pattern { magnet 2 julia <0.4, -0.2>, 20 interior 0, 1.5 exterior 1, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 62.", str(I, 0, 0), " ", str(F62(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 2 mandel interior 1 exterior 2
#declare F63 = function { pattern { magnet 2 mandel 20 interior 1, 1.5 exterior 2, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 63.", str(I, 0, 0), " ", str(F63(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 2 julia interior 1 exterior 2
#declare F64 = function { pattern { magnet 2 julia <0.4, -0.2>, 20 interior 1, 1.5 exterior 2, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 64.", str(I, 0, 0), " ", str(F64(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 2 mandel interior 4 exterior 6
#declare F65 = function { pattern { magnet 2 mandel 20 interior 4, 1.5 exterior 6, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 65.", str(I, 0, 0), " ", str(F65(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 2 julia interior 4 exterior 6
#declare F66 = function { pattern { magnet 2 julia <0.4, -0.2>, 20 interior 4, 1.5 exterior 6, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 66.", str(I, 0, 0), " ", str(F66(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 2 mandel interior 6 exterior 3
#declare F67 = function { pattern { magnet 2 mandel 20 interior 6, 1.5 exterior 3, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 67.", str(I, 0, 0), " ", str(F67(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// magnet 2 julia interior 6 exterior 3
#declare F68 = function { pattern { magnet 2 julia <0.4, -0.2>, 20 interior 6, 1.5 exterior 3, 0.9 frequency 0 } }
#for (I, 0, 9)
  #debug concat("V 68.", str(I, 0, 0), " ", str(F68(P_magnet[I].x, P_magnet[I].y, P_magnet[I].z), 0, 20), "\n")
#end
// bozo, generator 1
#declare F69 = function { pattern { bozo noise_generator 1 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 69.", str(I, 0, 0), " ", str(F69(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// bozo, generator 2
#declare F70 = function { pattern { bozo noise_generator 2 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 70.", str(I, 0, 0), " ", str(F70(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// bozo, generator 3
#declare F71 = function { pattern { bozo noise_generator 3 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 71.", str(I, 0, 0), " ", str(F71(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// spotted
#declare F72 = function { pattern { spotted frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 72.", str(I, 0, 0), " ", str(F72(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// bumps
#declare F73 = function { pattern { bumps noise_generator 3 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 73.", str(I, 0, 0), " ", str(F73(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// granite, generator 1
#declare F74 = function { pattern { granite noise_generator 1 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 74.", str(I, 0, 0), " ", str(F74(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// wrinkles, generator 1
#declare F75 = function { pattern { wrinkles noise_generator 1 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 75.", str(I, 0, 0), " ", str(F75(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// granite, generator 2
#declare F76 = function { pattern { granite noise_generator 2 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 76.", str(I, 0, 0), " ", str(F76(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// wrinkles, generator 2
#declare F77 = function { pattern { wrinkles noise_generator 2 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 77.", str(I, 0, 0), " ", str(F77(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// granite, generator 3
#declare F78 = function { pattern { granite noise_generator 3 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 78.", str(I, 0, 0), " ", str(F78(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// wrinkles, generator 3
#declare F79 = function { pattern { wrinkles noise_generator 3 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 79.", str(I, 0, 0), " ", str(F79(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// dents
#declare F80 = function { pattern { dents frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 80.", str(I, 0, 0), " ", str(F80(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// cells
#declare F81 = function { pattern { cells frequency 0 } }
#for (I, 0, 8)
  #debug concat("V 81.", str(I, 0, 0), " ", str(F81(P_g3_cells[I].x, P_g3_cells[I].y, P_g3_cells[I].z), 0, 20), "\n")
#end
// agate
#declare F82 = function { pattern { agate frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 82.", str(I, 0, 0), " ", str(F82(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// agate, agate_turb 0.6, octaves 4, omega 0.6, lambda 2.5
#declare F83 = function { pattern { agate agate_turb 0.6 octaves 4 omega 0.6 lambda 2.5 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 83.", str(I, 0, 0), " ", str(F83(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// agate, turbulence 0.4 (warped), generator 3
#declare F84 = function { pattern { agate turbulence 0.4 noise_generator 3 frequency 0 } }
#for (I, 0, 7)
  #debug concat("V 84.", str(I, 0, 0), " ", str(F84(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// marble, turbulence 0.5
#declare F85 = function { pattern { marble turbulence 0.5 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 85.", str(I, 0, 0), " ", str(F85(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// marble, turbulence <0.8,0,0>, octaves 3, generator 1
#declare F86 = function { pattern { marble turbulence <0.8, 0, 0> octaves 3 noise_generator 1 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 86.", str(I, 0, 0), " ", str(F86(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// wood, turbulence <0.3,0.2,0.1>
#declare F87 = function { pattern { wood turbulence <0.3, 0.2, 0.1> frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 87.", str(I, 0, 0), " ", str(F87(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// spiral1 4, turbulence 0.3 (warped)
#declare F88 = function { pattern { spiral1 4 turbulence 0.3 frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 88.", str(I, 0, 0), " ", str(F88(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// spiral2 2, turbulence <0.2,0.5,0.1> (warped)
#declare F89 = function { pattern { spiral2 2 turbulence <0.2, 0.5, 0.1> frequency 0 ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 89.", str(I, 0, 0), " ", str(F89(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// waves
#declare F90 = function { pattern { waves ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 90.", str(I, 0, 0), " ", str(F90(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// ripples
#declare F91 = function { pattern { ripples ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 91.", str(I, 0, 0), " ", str(F91(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// waves, frequency 2.5, phase 0.3
#declare F92 = function { pattern { waves frequency 2.5 phase 0.3 ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 92.", str(I, 0, 0), " ", str(F92(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// ripples, frequency 0.7, phase -0.45
#declare F93 = function { pattern { ripples frequency 0.7 phase -0.45 ramp_wave } }
#for (I, 0, 7)
  #debug concat("V 93.", str(I, 0, 0), " ", str(F93(P_g3[I].x, P_g3[I].y, P_g3[I].z), 0, 20), "\n")
#end
// crackle
#declare F94 = function { pattern { crackle frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 94.", str(I, 0, 0), " ", str(F94(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle form <1,0,0>
#declare F95 = function { pattern { crackle form <1, 0, 0> frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 95.", str(I, 0, 0), " ", str(F95(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle form <0,0,1>
#declare F96 = function { pattern { crackle form <0, 0, 1> frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 96.", str(I, 0, 0), " ", str(F96(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle form <0.8,-0.3,0.6> offset 0.2
#declare F97 = function { pattern { crackle form <0.8, -0.3, 0.6> offset 0.2 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 97.", str(I, 0, 0), " ", str(F97(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle metric 1
#declare F98 = function { pattern { crackle metric 1 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 98.", str(I, 0, 0), " ", str(F98(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle metric 1 form <1,0,0> offset 0.1
#declare F99 = function { pattern { crackle metric 1 form <1, 0, 0> offset 0.1 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 99.", str(I, 0, 0), " ", str(F99(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle metric 3 form <1,-0.5,0.25>
#declare F100 = function { pattern { crackle metric 3 form <1, -0.5, 0.25> frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 100.", str(I, 0, 0), " ", str(F100(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle metric 0.7 offset 0.3
#declare F101 = function { pattern { crackle metric 0.7 offset 0.3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 101.", str(I, 0, 0), " ", str(F101(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle solid
#declare F102 = function { pattern { crackle solid frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 102.", str(I, 0, 0), " ", str(F102(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle solid metric 1, generator 1
#declare F103 = function { pattern { crackle solid metric 1 noise_generator 1 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 103.", str(I, 0, 0), " ", str(F103(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
// crackle solid metric 2.5, generator 3
#declare F104 = function { pattern { crackle solid metric 2.5 noise_generator 3 frequency 0 } }
#for (I, 0, 11)
  #debug concat("V 104.", str(I, 0, 0), " ", str(F104(P_crackle[I].x, P_crackle[I].y, P_crackle[I].z), 0, 20), "\n")
#end
