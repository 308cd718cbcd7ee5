// povml fidelity scene: quadrics_disc_hole
// Rule: disc { C, N, R, H }: the ring H² ≤ r² ≤ R² in the plane through C with normal N, the
//       normal normalised at parse time and moved by every modifier (docs/povray-rules.md §15.4); the disc
//       is seen from both sides (the normal is flipped toward the ray, §3.1); shadows through
//       the hole (§4).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 3, -6> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
light_source { <5, 4, 6>, rgb 0.4 }
disc { <-1, 1.2, 0>, <0, 0, -1>, 1, 0.4 pigment { rgb <0.9, 0.5, 0.1> } finish { phong 0.5 } }
disc { <1.2, 1, 0.5>, <1, 0.5, 1>, 0.8 pigment { rgb <0.3, 0.8, 0.4> } }
disc { <0, 0, 0>, y, 0.6, 0.2 scale <1.5, 1, 0.8> rotate <0, 0, 20> translate <0.3, 0.6, -1.2> pigment { rgb <0.4, 0.5, 0.9> } }
disc { <0, 0.01, 0>, <0, 2, 0>, 3 pigment { rgb <0.85, 0.85, 0.8> } }
