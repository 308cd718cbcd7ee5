// povml fidelity scene: normal_wrinkles
// Rule: wrinkles adds ten octaves of the vector noise (at the point times 2^i, each component's
//       magnitude divided by 2^i) times the bump size (normal.cpp, wrinkles).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { wrinkles 0.8 scale 0.5 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> } normal { wrinkles 1 scale 0.3 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { wrinkles 0.6 scale <1, 0.1, 0.4> rotate y*30 } finish { specular 0.6 roughness 0.02 } }
