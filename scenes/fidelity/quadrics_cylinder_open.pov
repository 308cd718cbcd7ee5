// povml fidelity scene: quadrics_cylinder_open
// Rule: cylinder { … open }: no caps, so the inner wall is seen through the open ends and is lit
//       from inside where the light gets in (docs/povray-rules.md §15.2); the normal is flipped toward
//       the ray (§3.1). A closed twin beside it for comparison.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 3.5, -5> look_at <0, 0.5, 0> right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-3, 9, -4>, rgb 1 }
light_source { <4, 3, -5>, rgb 0.4 }
cylinder { <-0.9, 0, 0>, <-0.9, 1.4, 0>, 0.7 open pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.4 } }
cylinder { <1.2, 0.5, 0.5>, <1.2, 1.5, -0.2>, 0.5 open pigment { rgb <0.5, 0.8, 0.9> } finish { specular 0.5 } }
cylinder { <0.9, 0, -1.3>, <0.9, 0.5, -1.3>, 0.4 pigment { rgb <0.8, 0.3, 0.5> } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
