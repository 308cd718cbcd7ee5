// povml fidelity scene: quadrics_inverse_camera
// Rule: inverse on a primitive negates its Inside test only (docs/povray-rules.md §15.2, §20 item 7);
//       the camera stands inside the glass cylinder's bounding box but outside the cylinder, so
//       with inverse it starts "inside" it (§6.4) and every first crossing refracts as an exit.
//       (Without inverse the picture differs in 70% of its pixels.)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0.8, 1, -1.8> look_at <0, 0.8, 3> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
cylinder { <0, 0, -1>, <0, 1.6, -1>, 0.9 inverse pigment { rgbf <0.95, 1, 0.95, 0.9> } interior { ior 1.5 } }
cone { <1.5, 0, 0>, 0.6, <1.5, 1.5, 0>, 0.2 pigment { rgb <0.9, 0.4, 0.2> } }
box { <-1.8, 0, 1.5>, <-0.6, 1.6, 2.5> pigment { rgb <0.2, 0.6, 0.9> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
