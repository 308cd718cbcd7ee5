// povml fidelity scene: adc_bailout
// Rule: a child ray whose weight (parent weight * max(refl), or * max|filCol| for transmission)
//       is below adc_bailout returns black; a transmitted ray is traced only if
//       trans = min(1, |grey(filCol)|) > adc_bailout (docs/povray-rules.md §7, §6.1, pitfall §13.13).
// adc_bailout 0.5. Left ball: reflection 0.3 (reflected ray weight 0.3: black reflection).
// Second: reflection 0.7 (reflected, but its own reflections are cut: weight 0.49).
// Third: rgbt 0.8 (transmitted, see-through). Right: rgbt 0.4 (trans 0.4: no transmitted ray).
// The back wall is a reflection 0.7 mirror.
#version 3.7;
global_settings { assumed_gamma 1.0 adc_bailout 0.5 }
camera { location <0, 1.4, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.9, 0.9, 0.6> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.4, 0.8, 0>, 0.65 pigment { rgb 0.1 } finish { reflection 0.3 } }
sphere { <-0.8, 0.8, 0>, 0.65 pigment { rgb 0.1 } finish { reflection 0.7 } }
sphere { < 0.8, 0.8, 0>, 0.65 pigment { rgbt <1, 0.6, 0.6, 0.8> } }
sphere { < 2.4, 0.8, 0>, 0.65 pigment { rgbt <0.6, 0.6, 1, 0.4> } }
sphere { < 0.0, 0.4, -2.0>, 0.3 pigment { rgb <0.1, 0.8, 0.2> } }
plane { z, 3 pigment { rgb 0.1 } finish { reflection 0.7 } }
plane { y, 0 pigment { rgb <0.7, 0.5, 0.4> } }
