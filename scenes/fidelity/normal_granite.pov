// povml fidelity scene: normal_granite
// Rule: every pattern without a normal of its own bends the normal by the tetrahedral finite
//       difference of its value (normal.cpp, Perturb_Normal; the value as Evaluate_TPat gives
//       it, with the normal's noise generator): granite on the floor, wood with its own
//       turbulence on the sphere, crackle on the box's faces, marble behind them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { granite 0.5 scale 2 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { wood 0.8 turbulence 0.2 scale 0.15 noise_generator 1 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { crackle 1 scale 0.3 } finish { specular 0.6 roughness 0.02 } }
box { <-3, 0, 2.5>, <3, 2.5, 3> pigment { rgb <0.7, 0.8, 0.6> }
      normal { marble 0.6 turbulence 0.8 scale 0.7 } finish { phong 0.3 } }
