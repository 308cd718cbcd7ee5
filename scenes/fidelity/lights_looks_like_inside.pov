// povml fidelity scene: lights_looks_like_inside
// Rule: a camera inside a light's looks_like object starts inside it, as inside any object: the
//       ray leaving the glass ball refracts from ior 1.5 to 1 (checked against POV-Ray 3.7.0.10;
//       docs/povray-rules.md §19.2 says the opposite, and its rendering differs in 79% of the pixels).
//       §6.4.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 1.2, -0.2> look_at <0, 0.8, 3> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
light_source {
  <0, 1, 0>, rgb 1
  looks_like { sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 } interior { ior 1.5 } } }
}
light_source { <-3, 6, -4>, rgb 0.6 }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } }
sphere { <-0.8, 0.5, 3>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } }
box { <0.3, 0, 2.5>, <1.2, 1.5, 3.3> pigment { rgb <0.3, 0.6, 0.9> } }
