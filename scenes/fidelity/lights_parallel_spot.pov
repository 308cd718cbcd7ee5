// povml fidelity scene: lights_parallel_spot
// Rule: a parallel spotlight: the light ray is the spot axis itself, cos = 1 in front of the
//       light's plane, so no cone is seen (docs/povray-rules.md §18.3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.3, 0> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
light_source { <1, 5, -2>, rgb 1 spotlight radius 5 falloff 8 parallel point_at <0, 0, 0> }
light_source { <-6, 8, -6>, rgb 0.15 }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } }
sphere { <-1.2, 0.6, 0.4>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.8 phong_size 40 } }
sphere { <1.1, 0.5, -0.3>, 0.5 pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.5 } }
box { <-0.3, 0, 1.2>, <0.5, 1.1, 2> pigment { rgb <0.4, 0.8, 0.3> } }
