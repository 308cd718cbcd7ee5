// povml fidelity scene: shadowless_light
// Rule: a `shadowless` light is a fill light: no shadow test and NO phong/specular highlights,
//       but normal diffuse (docs/povray-rules.md §3.3, §10.2, pitfall §13.7).
// A dim ordinary light (left, above) gives one highlight per sphere and shadows; the brighter
// shadowless light (right, low) adds diffuse light only: no second highlight, no second shadow.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.12> }
light_source { <-4, 6, -4>, rgb 0.45 }
light_source { < 5, 2.5, -4>, rgb <0.9, 0.85, 0.7> shadowless }
sphere { <-1.2, 0.9, 0>, 0.8 pigment { rgb <0.8, 0.3, 0.3> } finish { phong 1 phong_size 60 } }
sphere { < 1.2, 0.9, 0>, 0.8 pigment { rgb <0.3, 0.5, 0.8> } finish { specular 1 roughness 0.02 } }
plane { y, 0 pigment { rgb 0.7 } }
