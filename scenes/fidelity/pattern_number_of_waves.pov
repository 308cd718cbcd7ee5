// povml fidelity scene: pattern_number_of_waves
// Rule: global_settings { number_of_waves 3 } gives waves and ripples three wave sources, in
//       pigments and in normals (Initialize_Waves: the first sources of the default ten).
#version 3.7;
global_settings { assumed_gamma 1 number_of_waves 3 }
camera { location <0, 3, -4> look_at <0, 0.5, 0> angle 60 }
light_source { <-3, 10, -6> rgb 1 }
#declare C = color_map { [0 rgb <0.1, 0, 0.4>] [0.3 rgb <0, 0.7, 0.2>] [0.6 rgb <1, 0.8, 0>] [1 rgb <1, 0.1, 0.1>] }
plane { y, 0 pigment { ripples color_map { C } scale 0.5 } finish { ambient 0.5 diffuse 0.5 } normal { waves 0.6 scale 0.3 } }
sphere { <0, 1, 0>, 1 pigment { waves color_map { C } scale 0.5 } finish { ambient 0.3 diffuse 0.7 } normal { ripples 0.8 scale 0.4 } }
