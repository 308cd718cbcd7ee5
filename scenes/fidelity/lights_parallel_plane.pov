// povml fidelity scene: lights_parallel_plane
// Rule: a parallel light's shadow ray runs only as far as the plane through its centre
//       perpendicular to its direction: a point behind that plane is lit but never shadowed, and
//       objects behind it cast no shadow (docs/povray-rules.md §18.3).
// The light's plane is y = 1.2: the sphere above it is lit from above and casts no shadow on the
// floor, the sphere below it casts one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
light_source { <0, 1.2, 0>, rgb 1 parallel point_at <0.3, 0, 0.2> }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } }
sphere { <-1.3, 2.2, 0>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <1.3, 0.6, 0>, 0.5 pigment { rgb <0.3, 0.6, 0.9> } }
box { <-0.4, 0.9, -0.4>, <0.4, 1.6, 0.4> rotate <0, 30, 0> pigment { rgb <0.4, 0.8, 0.3> } }
