// povml fidelity scene: quadrics_camera_in_four
// Rule: with the camera inside several transparent objects, which one counts as entered last
//       decides each first crossing's ratio of indices (docs/povray-rules.md §6.2, §6.4). POV-Ray lists
//       the containing objects in the order of a depth-first walk of its bounding-slab tree
//       (sort_and_split: sorted along the axis find_axis picks, split by the surface-area rule,
//       at most 4 to a node), asking each node's box before the object's Inside test; the last
//       found is the last entered. Here the camera is inside a closed glass cylinder, an open
//       glass cylinder (solid inside), a glass sphere and an open-ended glass cone, written in an
//       order unlike the tree's.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0.1, 1, -0.5> look_at <0.3, 0.8, 4> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
box { <-1.8, 0, 3.5>, <-0.6, 1.6, 4.5> pigment { rgb <0.2, 0.6, 0.9> } }
sphere { <0.8, 0.8, 4>, 0.7 pigment { rgb <0.9, 0.4, 0.2> } }
sphere { <0.2, 1, -0.4>, 0.9 pigment { rgbf <0.9, 0.9, 1, 0.9> } interior { ior 1.6 } }
cone { <0, 0, -0.5>, 1, <0, 2, -0.5>, 0.3 open pigment { rgbf <1, 1, 0.9, 0.9> } interior { ior 1.1 } }
cylinder { <0, 0.2, -2>, <0, 0.2, 2.5>, 1.6 pigment { rgbf <0.95, 1, 0.95, 0.9> } interior { ior 1.4 } }
disc { <-1, 0.5, 2.8>, <0.2, 0, -1>, 0.5 pigment { rgb <0.9, 0.9, 0.3> } }
cylinder { <0, -1, -0.5>, <0, 3, -0.5>, 0.6 open pigment { rgbf <1, 0.9, 0.9, 0.95> } interior { ior 1.2 } }
cone { <2, 0, 5>, 0.5, <2.2, 1.5, 5>, 0.1 pigment { rgb <0.7, 0.3, 0.9> } }
cylinder { <1.5, 0, 3>, <1.5, 2, 3.5>, 0.3 pigment { rgb <0.3, 0.9, 0.3> } }
