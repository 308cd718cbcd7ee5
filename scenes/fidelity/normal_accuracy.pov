// povml fidelity scene: normal_accuracy
// Rule: accuracy is the size of the tetrahedron the finite difference samples (0.02 by default,
//       single precision), and the bend is scaled by 0.02/accuracy (normal.cpp): a coarse
//       accuracy blurs the sine-waved gradient's slope and the cliffs of a ramp; a fine one
//       follows them. Floor strips: accuracy 0.3, 0.02, 0.002; sphere 0.15; box 0.05.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
#declare F = finish { phong 0.4 }
box { <-4, -1, -2>, <-1.5, 0, 4> pigment { rgb 0.8 } normal { gradient z 0.6 sine_wave accuracy 0.3 scale 0.5 } finish { F } }
box { <-1.5, -1, -2>, <1, 0, 4> pigment { rgb 0.8 } normal { gradient z 0.6 sine_wave scale 0.5 } finish { F } }
box { <1, -1, -2>, <4, 0, 4> pigment { rgb 0.8 } normal { gradient z 0.6 accuracy 0.002 scale 0.5 } finish { F } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { gradient y 1 accuracy 0.15 scale 0.2 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { gradient <1, 1, 0> 0.7 cubic_wave accuracy 0.05 scale 0.3 } finish { specular 0.6 roughness 0.02 } }
