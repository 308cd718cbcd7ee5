// povml fidelity scene: reflection_mirrors
// Rule: plain `reflection C`: reflected ray R = D - 2(D.N)N from the hit point, colour added as
//       refl*colour_r, recursion until max_trace_level (a cut-off ray returns black) or the ray
//       weight drops below adc_bailout (docs/povray-rules.md §5.1, §5.3, §7).
// Two parallel mirror planes (x = -2 and x = +2) face each other; a red and a green ball stand
// between them, giving a corridor of repeated images that darkens with depth. max_trace_level 12.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0.3, 1.6, -5> look_at <-1.0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.5, 0.8> }
light_source { <0.5, 5, -3>, rgb 1 }
plane { x, 2 pigment { rgb <0.8, 0.9, 0.8> } finish { ambient 0 diffuse 0.1 reflection 0.85 } }
plane { -x, 2 pigment { rgb <0.8, 0.8, 0.9> } finish { ambient 0 diffuse 0.1 reflection 0.85 } }
sphere { <-0.6, 0.7, 0.5>, 0.6 pigment { rgb <0.9, 0.2, 0.15> } finish { phong 0.7 } }
sphere { < 0.9, 0.5, 1.8>, 0.45 pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.7 } }
plane { y, 0 pigment { rgb <0.9, 0.85, 0.7> } }
