// povml fidelity scene: normal_dents
// Rule: dents adds the vector noise times the cube of the scalar noise times the bump size
//       (normal.cpp, dents): the scalar noise with the normal's noise generator (the scene's,
//       2, on the floor; 1 on the sphere; 3 on the box).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { dents 2 scale 0.15 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> } normal { dents 3 noise_generator 1 scale 0.2 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { dents 3 noise_generator 3 scale 0.25 } finish { specular 0.6 roughness 0.02 } }
