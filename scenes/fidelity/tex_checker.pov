// povml fidelity scene: tex_checker
// Rule: block patterns choose among listed textures (checker texture {…} texture {…}, hexagon,
//       brick with three and two; missing ones are the default texture) and tiles { … tile2 … }
//       is a checker whose first texture sits where the checker's value is 1.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 texture { checker texture { pigment { rgb <0.9, 0.9, 0.8> } finish { reflection 0.3 } } texture { pigment { rgb <0.2, 0.3, 0.2> } } scale 0.7 } }
sphere { <-1.1, 1, 0.5>, 1 texture { hexagon texture { pigment { rgb <1, 0.2, 0.2> } } texture { pigment { rgb <0.2, 1, 0.2> } normal { dents 1 scale 0.1 } } texture { pigment { rgbt <0.2, 0.2, 1, 0.5> } } scale 0.3 rotate x*90 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { tiles { texture { pigment { rgb <1, 0.8, 0.3> } finish { phong 1 } } tile2 texture { pigment { rgb <0.3, 0.3, 0.9> } } texture { pigment { rgbt <1, 1, 1, 0.5> } } } scale 0.3 } }
sphere { <0.4, 1.7, 1>, 0.4 texture { brick texture { pigment { rgb 0.9 } } scale 0.05 } }
