// povml fidelity scene: pattern_ripples_frequency
// Rule: ripples and waves use the pattern's frequency and phase inside their value, and the wrap
//       of §17.1 uses them again (pattern.cpp ripples_pattern, waves_pattern).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at <0, 0.5, 0> angle 60 }
#declare C = color_map { [0 rgb <0.1, 0, 0.4>] [0.3 rgb <0, 0.7, 0.2>] [0.6 rgb <1, 0.8, 0>] [1 rgb <1, 0.1, 0.1>] }
plane { y, 0 pigment { ripples frequency 3 phase 0.3 color_map { C } scale 0.5 } finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1 pigment { waves frequency 2.5 phase 0.7 color_map { C } scale 0.5 } finish { ambient 1 diffuse 0 } }
