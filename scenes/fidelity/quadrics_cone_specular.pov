// povml fidelity scene: quadrics_cone_specular
// Rule: cone { P1, r1, P2, r2 }: the bigger end becomes the canonical top z = 1, the apex at z = 0,
//       the small end at z = dist = r_small/r_big (docs/povray-rules.md §15.3); side normal (x, y, −z);
//       specular highlights (§3.3). One cone written big end first, one small end first.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 3, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
light_source { <5, 4, -6>, rgb 0.3 }
cone { <-1.2, 0, 0>, 0.8, <-1.2, 1.8, 0>, 0.2 pigment { rgb <0.9, 0.5, 0.1> } finish { specular 0.7 roughness 0.01 } }
cone { <0.9, 0.2, -0.3>, 0.15, <1.6, 1.4, 0.8>, 0.6 pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.5 } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
