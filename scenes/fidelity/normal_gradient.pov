// povml fidelity scene: normal_gradient
// Rule: a normal pattern without a normal of its own bends the normal by the slope of its value,
//       sampled at the four corners of a tetrahedron of size accuracy (0.02) around the point
//       and weighted by −5·bump_size (normal.cpp, Perturb_Normal). gradient x with ramp_wave
//       is a saw: lit ridges on the floor; a triangle_wave gradient on a sphere, a sine_wave
//       one on a box; phong highlights and the diffuse term follow the bent normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
light_source { <4, 3, -2>, rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { gradient x 0.6 scale 0.5 } finish { phong 0.5 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { gradient y 1.5 triangle_wave scale 0.2 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { gradient <1, 1, 0> 0.8 sine_wave frequency 3 } finish { specular 0.6 roughness 0.02 } }
