// povml fidelity scene: uv_normal
// Rule: normal { uv_mapping … } perturbs the normal with the pattern at the hit's (u, v, 0) and
//       normalises the result (Perturb_Normal's UV_MAP_PATTERN case); left a slope-of-value
//       pattern (gradient), middle bumps, right a normal_map with a uv-mapped entry.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
sphere { <-1.8, 0, 0>, 0.8 pigment { rgb <1, 0.8, 0.6> } finish { phong 0.6 }
  normal { uv_mapping gradient x 2 scale 0.1 } }
sphere { <0, 0, 0>, 0.8 pigment { rgb <0.7, 0.9, 1> } finish { phong 0.6 }
  normal { uv_mapping bumps 1.5 scale 0.05 } rotate y*30 }
sphere { <1.8, 0, 0>, 0.8 pigment { rgb <0.8, 1, 0.7> } finish { phong 0.6 }
  normal { gradient y normal_map { [0.5 uv_mapping wrinkles 1 scale <0.05, 0.1, 1>] [0.5 bumps 0.5 scale 0.1] } } }
plane { y, -1 pigment { rgb 0.6 } }
