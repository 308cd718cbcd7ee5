// povml fidelity scene: reflection_exponent
// Rule: with reflection exponent E != 1 the reflected colour is added as refl * colour_r^(1/E)
//       per channel; `reflection_exponent E` and `reflection { .. exponent E }` both store 1/E
//       (docs/povray-rules.md §5.1, §5.3).
// Left: reflection 0.6 (E = 1). Middle: reflection 0.6 reflection_exponent 0.5 (darker reflected
// image). Right: reflection { 0.6 exponent 2.5 } (brighter, washed-out reflected image).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.6, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.45, 0.7> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.1, 0.9, 0>, 0.85 pigment { rgb 0.05 } finish { reflection 0.6 } }
sphere { < 0.0, 0.9, 0>, 0.85 pigment { rgb 0.05 } finish { reflection 0.6 reflection_exponent 0.5 } }
sphere { < 2.1, 0.9, 0>, 0.85 pigment { rgb 0.05 } finish { reflection { 0.6 exponent 2.5 } } }
sphere { <-1.0, 0.35, -1.6>, 0.3 pigment { rgb <1, 0.5, 0.1> } }
sphere { < 1.1, 0.35, -1.5>, 0.3 pigment { rgb <0.3, 0.2, 0.9> } }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.5> } }
