// povml fidelity scene: camera_angle
// Rule: `angle A` sets the HORIZONTAL field of view across |right|: |direction| = |right|/(2 tan(A/2)),
//       applied before look_at; right = x*image_width/image_height (docs/povray-rules.md §1.3, pitfall §13.4).
// angle 35 (a telephoto view): the middle ball fills most of the width; a 90 degree default
// would show all five balls small.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.8, 0> right x*image_width/image_height angle 35 }
background { rgb <0.4, 0.5, 0.7> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.0, 0.6, 0>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { <-1.0, 0.6, 0>, 0.4 pigment { rgb <0.9, 0.6, 0.1> } }
sphere { < 0.0, 0.8, 0>, 0.7 pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.6 } }
sphere { < 1.0, 0.6, 0>, 0.4 pigment { rgb <0.2, 0.6, 0.9> } }
sphere { < 2.0, 0.6, 0>, 0.5 pigment { rgb <0.6, 0.2, 0.9> } }
plane { y, 0 pigment { rgb 0.75 } }
