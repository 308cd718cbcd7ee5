// povml fidelity scene: lights_parallel_fade
// Rule: a parallel light's fade uses the point's depth in front of the light's plane, not its
//       distance to the centre (docs/povray-rules.md §18.3, §3.4); a spotlight's fade its distance.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.3, 0> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
light_source { <-2, 3, 0>, rgb 1 parallel point_at <0, 0, 1> fade_distance 2 fade_power 2 }
light_source { <2, 4, -2>, rgb <0.6, 0.5, 0.3> spotlight radius 20 falloff 40 point_at <1, 0, 1> fade_distance 3 fade_power 1 }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } }
sphere { <-1.2, 0.6, 0.4>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.8 phong_size 40 } }
sphere { <1.1, 0.5, -0.3>, 0.5 pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.5 } }
box { <-0.3, 0, 1.2>, <0.5, 1.1, 2> pigment { rgb <0.4, 0.8, 0.3> } }
