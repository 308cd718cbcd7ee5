// povml fidelity scene: image_bump_use_index
// Rule: bump_map use_index: palette indices as heights
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
light_source { <-3, 5, -6> rgb 1 }
plane { z, 0 pigment { rgb 0.8 } normal { bump_map { gif "../images/img.gif" use_index bump_size 0.05 } } }
