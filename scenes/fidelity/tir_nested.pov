// povml fidelity scene: tir_nested
// Rule: total internal reflection: when t = 1 + ior^2 (n^2 - 1) < 0 the ray is mirrored instead of
//       refracted, traced at trace level + 1 and added UNFILTERED, and no separate reflection ray is
//       traced (docs/povray-rules.md §6.2, §6.3, §5.3). (A ray that enters a lone sphere from outside can
//       never meet TIR, so the TIR here happens at an inner, lower-ior object: ratio n_outer/n_inner.)
// Left: a diamond-like ball (ior 2.4) with an off-centre core of ior 1.2 (ratio 2.0, critical
// angle 30 degrees): the core looks like a bright silvery mirror. Right: a glass ball (ior 1.5)
// with a large air bubble (ior 1.0): silvery rim around the bubble. max_trace_level 10.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1.6, -6> look_at <0, 1.0, 0> right x*image_width/image_height }
background { rgb <0.2, 0.25, 0.35> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-1.3, 1.1, 0>, 1.0 pigment { rgbf <1, 1, 1, 0.97> } finish { ambient 0 diffuse 0 phong 1 phong_size 200 } interior { ior 2.4 } }
sphere { <-1.2, 1.2, -0.1>, 0.55 pigment { rgbf <1, 1, 1, 0.97> } finish { ambient 0 diffuse 0 } interior { ior 1.2 } }
sphere { < 1.3, 1.1, 0>, 1.0 pigment { rgbf <1, 1, 1, 0.97> } finish { ambient 0 diffuse 0 phong 1 phong_size 200 } interior { ior 1.5 } }
sphere { < 1.35, 1.15, -0.1>, 0.7 pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } interior { ior 1.0 } }
sphere { <-1.8, 0.58, 3.0>, 0.5 pigment { rgb <0.9, 0.3, 0.1> } }
sphere { < 1.6, 0.7, 3.0>, 0.6 pigment { rgb <0.1, 0.6, 0.9> } }
sphere { < 0.0, 3.0, 3.5>, 0.7 pigment { rgb <0.9, 0.9, 0.2> } }
plane { y, 0 pigment { rgb <0.7, 0.8, 0.7> } }
