// povml fidelity scene: normal_waves
// Rule: waves is ripples with each source's own frequency (from Initialize_Waves's random
//       sequence) multiplying the distance and dividing the amplitude (normal.cpp, waves).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { waves 0.6 scale 0.3 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> } normal { waves 0.8 frequency 4 scale 0.5 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { waves 1 phase 0.5 frequency 2 scale 0.2 } finish { specular 0.6 roughness 0.02 } }
