// povml fidelity scene: light_fade
// Rule: light attenuation a = 2 / (1 + (dist/fade_distance)^fade_power), only when fade_power > 0
//       and fade_distance != 0 (factor 2: brighter than full inside fade_distance)
//       (docs/povray-rules.md §3.4, pitfall §13.6).
// Left light: fade_distance 1.5 fade_power 2 (quadratic falloff pool on the floor).
// Right light: fade_distance 2 fade_power 1 (linear, wider pool).
// Third light: fade_distance 1 but no fade_power, so NO attenuation (uniform dim blue fill).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0, 0.5> right x*image_width/image_height }
background { rgb 0 }
light_source { <-2.5, 1.2, 0>, rgb <0.5, 0.45, 0.3> fade_distance 1.5 fade_power 2 }
light_source { < 2.5, 1.5, 1>, rgb <0.3, 0.45, 0.5> fade_distance 2 fade_power 1 }
light_source { < 0, 8, -3>, rgb <0.05, 0.05, 0.12> fade_distance 1 }
sphere { <0, 0.7, 0.5>, 0.6 pigment { rgb 0.9 } finish { ambient 0.02 diffuse 0.8 } }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.02 diffuse 0.8 } }
