// povml fidelity scene: normal_facets_coords
// Rule: facets coords V: the cube points are searched near the scaled point, and V (a number, not
//       a switch) scales the vector noise that bends the normal (normal.cpp facets).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at <0, 0.5, 0> angle 60 }
light_source { <-3, 10, -6> rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.7, 0.5> } normal { facets coords 0.4 size 0.5 } finish { phong 0.6 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.5, 0.7, 0.9> } normal { facets coords 2.5 size 0.3 } finish { phong 0.8 } }
