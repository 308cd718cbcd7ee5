// povml fidelity scene: patterns_hexagon
// Rule: hexagon's three-colour tiling of the XZ plane, defaults blue, green, red
//       (docs/povray-rules.md §17.6); scaled and rotated in the pigment.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 7, -6> look_at <0, 0, 0> right x*image_width/image_height }
light_source { <3, 10, -4> color rgb 1 }
plane { y, 0 pigment { hexagon rgb <0.9, 0.8, 0.2>, rgb <0.2, 0.3, 0.8>, rgb <0.8, 0.2, 0.3> scale 0.8 } }
sphere { <1.5, 1, 0>, 1 pigment { hexagon scale 0.3 rotate <90, 0, 20> } }
box { <-3, 0, 0>, <-1, 2, 2> pigment { hexagon rgb 1 scale 0.4 } }
