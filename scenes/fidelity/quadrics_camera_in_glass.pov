// povml fidelity scene: quadrics_camera_in_glass
// Rule: the camera inside a closed glass cylinder starts with it in its interior list, found by
//       the cylinder's Inside test (shrunk by EPSILON) (docs/povray-rules.md §6.4, §15.2). The camera is
//       also behind a glass disc (on the side opposite its normal, §15.4) but outside the disc's
//       thin bounding box, and POV-Ray asks the box first: the disc is NOT in the starting list.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1, -1> look_at <0, 0.8, 3> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
cylinder { <0, 0.2, -2>, <0, 0.2, 1.5>, 1.5 pigment { rgbf <0.95, 1, 0.95, 0.9> } finish { phong 0.5 } interior { ior 1.4 } }
disc { <0, 0.9, 2.5>, <0, 0, 1>, 0.6 pigment { rgbf <0.9, 0.9, 1, 0.7> } interior { ior 1.3 } }
sphere { <0.8, 0.8, 4>, 0.7 pigment { rgb <0.9, 0.4, 0.2> } }
box { <-1.8, 0, 3.5>, <-0.6, 1.6, 4.5> pigment { rgb <0.2, 0.6, 0.9> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
