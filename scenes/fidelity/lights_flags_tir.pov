// povml fidelity scene: lights_flags_tir
// Rule: a ray totally internally reflected inside glass is a reflection ray, and so is the ray that
//       leaves the glass after it: no_reflection objects are absent from what it sees and no_image
//       objects present (docs/povray-rules.md §16.6; checked: treating it as an image ray differs in over
//       a thousand pixels). A glass box turned 30° sends every ray entering its front face into
//       total internal reflection at a side face.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 1, -5> look_at <0, 1, 0> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } }
box { <-1, 0.2, -1>, <1, 1.8, 1> rotate <0, 30, 0> pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 } interior { ior 1.5 } }
box { <-6, 0.01, 3.07>, <-1, 3.63, 3.5> pigment { rgb <0.9, 0.3, 0.2> } no_reflection }
box { <1.03, 0.01, 3.07>, <6, 3.63, 3.5> pigment { rgb <0.3, 0.9, 0.2> } no_image }
box { <3, 0.01, -3>, <3.5, 3.63, 3> pigment { rgb <0.3, 0.3, 0.9> } no_reflection }
box { <-3.5, 0.01, -3>, <-3, 3.63, 3> pigment { rgb <0.9, 0.9, 0.2> } no_image }
