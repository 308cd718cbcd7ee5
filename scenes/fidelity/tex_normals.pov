// povml fidelity scene: tex_normals
// Rule: each layer is shaded with its own normal, and a normal inside a patterned texture is bent
//       in the space of the patterns around it (Warp_Normal of each enclosing texture).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 texture { pigment { rgb <0.8, 0.75, 0.7> } normal { bumps 0.5 scale 0.2 } finish { phong 0.4 } }
        texture { pigment { rgbt <0.1, 0.1, 0.6, 0.7> } normal { ripples 0.8 scale 0.5 } finish { specular 0.5 } } }
sphere { <-1.1, 1, 0.5>, 1 texture { checker texture { pigment { rgb <1, 0.4, 0.2> } normal { gradient x 2 scale 0.1 } finish { phong 0.8 } } texture { pigment { rgb <0.9, 0.9, 0.3> } normal { bumps 1 scale 0.1 } } scale <2, 0.5, 1> rotate 20*z } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { granite texture_map { [0.4 pigment { rgb <0.3, 0.5, 0.9> } normal { dents 1 scale 0.2 }] [0.6 pigment { rgb 0.9 } normal { wrinkles 1 scale 0.3 } finish { reflection 0.2 }] } scale <0.5, 2, 1> } }
