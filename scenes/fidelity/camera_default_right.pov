// povml fidelity scene: camera_default_right
// Rule: the default right vector is <1.33,0,0> (not 4/3, not adjusted to the image size) and
//       look_at keeps its length (docs/povray-rules.md §1.1, §1.3, pitfall §13.2).
// No `right` keyword. At 160x120 the balls look round; on a non-4:3 image they would be squashed.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> }
background { rgb <0.4, 0.5, 0.7> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.0, 0.6, 0>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { < 0.0, 0.8, 0>, 0.7 pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.6 } }
sphere { < 2.0, 0.6, 0>, 0.5 pigment { rgb <0.2, 0.6, 0.9> } }
plane { y, 0 pigment { rgb 0.75 } }
