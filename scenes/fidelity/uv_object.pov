// povml fidelity scene: uv_object
// Rule: uv_mapping on an object (before its texture): all its textures are evaluated at the hit's
//       (u, v, 0), normals included, and later transforms of the object leave the textures
//       (objects.cpp, UV_FLAG); in a CSG the members that take the parent's texture too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-1.1, 1, 0.5>, 1 uv_mapping texture { pigment { checker rgb <1, 0.3, 0.2>, rgb 0.9 scale <0.125, 0.25, 1> } normal { bumps 0.5 scale 0.05 } finish { phong 0.6 } } rotate 20*z }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> uv_mapping texture { pigment { gradient y color_map { [0 rgb <0.2, 0.2, 0.9>] [1 rgb 1] } } } translate 0.1*x }
union { sphere { <0.3, 1.9, 1.5>, 0.4 } sphere { <0.9, 1.9, 1.5>, 0.4 } uv_mapping pigment { gradient x color_map { [0 rgb <0, 1, 0>] [1 rgb <1, 0, 1>] } } }
