// povml fidelity scene: brilliance
// Rule: diffuse term uses (N.L)^brilliance (exponent skipped when brilliance == 1)
//       (docs/povray-rules.md §3.3, ComputeDiffuseColour).
// Left to right: brilliance 0.3 (flat, wide), 1 (Lambert), 5 (narrow, dark terminator).
// The light comes from the upper right so the terminator is visible on every sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.0, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.12> }
light_source { <5, 6, -5>, rgb 1 }
sphere { <-2.2, 0.8, 0>, 0.9 pigment { rgb <0.9, 0.8, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 0.3 } }
sphere { <0, 0.8, 0>, 0.9 pigment { rgb <0.9, 0.8, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 1 } }
sphere { <2.2, 0.8, 0>, 0.9 pigment { rgb <0.9, 0.8, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 5 } }
plane { y, -0.3 pigment { rgb <0.5, 0.55, 0.6> } finish { brilliance 2 } }
