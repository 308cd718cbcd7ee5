// povml fidelity scene: shadow_beyond_light
// Rule: a shadow-ray hit only counts if 1e-3 < t < dist_to_light - 1e-3: objects at or BEYOND
//       the light never shadow (docs/povray-rules.md §4, §2.1; lecture "they might be beyond the light!").
// The light hangs at y = 2.5 under a big red ball (y 3.5 .. 5.5). Points on the floor whose ray
// toward the light would continue into the red ball must stay fully lit: the floor shows a lit
// pool with only the small blue ball's shadow (that ball is between the light and the floor).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7> look_at <0, 1.5, 0> right x*image_width/image_height }
background { rgb <0.05, 0.05, 0.08> }
light_source { <0, 2.5, 0>, rgb 1 }
sphere { <0, 4.5, 0.5>, 1.0 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { <1.0, 1.3, 0.3>, 0.35 pigment { rgb <0.2, 0.4, 0.9> } }
plane { y, 0 pigment { rgb 0.8 } }
