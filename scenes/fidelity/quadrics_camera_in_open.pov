// povml fidelity scene: quadrics_camera_in_open
// Rule: an open cylinder still has a solid inside, grown by EPSILON (docs/povray-rules.md §15.2, §20 item
//       7): a camera inside an open glass cylinder starts with it in its interior list (§6.4), so
//       the rays leaving through its wall refract as exits. A glass cone stands outside.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1, -1> look_at <0, 0.8, 3> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
cylinder { <0, 0.5, -1.5>, <0, 0.5, 2>, 1.2 open pigment { rgbf <1, 0.9, 0.9, 0.95> } finish { phong 0.4 } interior { ior 1.2 } }
cone { <1, 0, 3>, 0.6, <1.2, 1.4, 3.2>, 0.1 pigment { rgbf <0.8, 1, 0.8, 0.8> } interior { ior 1.5 } }
sphere { <0.8, 0.8, 5>, 0.7 pigment { rgb <0.9, 0.4, 0.2> } }
box { <-1.8, 0, 3.5>, <-0.6, 1.6, 4.5> pigment { rgb <0.2, 0.6, 0.9> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
