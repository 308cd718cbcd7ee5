// povml fidelity scene: ambient_diffuse
// Rule: local colour = C*ambient*ambient_light*att + sum over lights of C*lc*(N.L)*diffuse*att
//       (docs/povray-rules.md §3.2, §3.3; default finish ambient 0.1 diffuse 0.6, §10.1).
// Left: ambient 0.6 diffuse 0 (flat disc).  Middle: default finish (no finish block).
// Right: ambient 0 diffuse 1 (black where N.L <= 0).  Floor: ambient 0.2 diffuse 0.5.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -6> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.05, 0.05, 0.1> }
light_source { <-4, 6, -5>, rgb 1 }
sphere { <-2.2, 0.8, 0>, 0.9 pigment { rgb <0.9, 0.3, 0.2> } finish { ambient 0.6 diffuse 0 } }
sphere { <0, 0.8, 0>, 0.9 pigment { rgb <0.2, 0.8, 0.3> } }
sphere { <2.2, 0.8, 0>, 0.9 pigment { rgb <0.3, 0.4, 0.9> } finish { ambient 0 diffuse 1 } }
plane { y, -0.2 pigment { rgb 0.7 } finish { ambient 0.2 diffuse 0.5 } }
