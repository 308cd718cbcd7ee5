// povml fidelity scene: torus_tiny
// Rule: a torus keeps R and r in its own space and the scale in its transform (§14.4), so a tiny
//       torus scaled up still solves a quartic with tiny coefficients (about R⁴ for the constant
//       term): difficult() sees coefficients more than 1e12 apart and switches to Sturm
//       sequences, whose remainders lose coefficients below 1e-10, and root elimination compares
//       |c4/c3| with 1e-4 in torus units (docs/povray-rules.md §15.6). Each torus here is about the same
//       size on screen; their pixels show where POV-Ray's solver finds roots and where it loses
//       them (with difficult() switched off, 540 pixels differ from POV-Ray's picture).
// Four tori scaled to about the same size, over a floor: R = 1, r = 0.3; R = 0.01, r = 0.003;
// R = 0.001, r = 0.0001; R = 0.0003, r = 0.00006.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.3, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -5>, rgb 1 }
light_source { <4, 3, -6>, rgb 0.3 }
torus { 1, 0.3 rotate x*-50 translate <-2.4, 0.8, 0> pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
torus { 0.01, 0.003 scale 100 rotate x*-50 translate <-0.8, 0.8, 0> pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.6 } }
torus { 0.001, 0.0001 scale 1000 rotate x*-50 translate <0.8, 0.8, 0> pigment { rgb <0.3, 0.5, 0.9> } finish { phong 0.6 } }
torus { 0.0003, 0.00006 scale 3000 rotate x*-50 translate <2.4, 0.8, 0> pigment { rgb <0.9, 0.8, 0.3> } finish { phong 0.6 } }
plane { y, -0.5 pigment { rgb <0.85, 0.85, 0.8> } }
