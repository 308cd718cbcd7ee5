// povml fidelity scene: pattern_pavement
// Rule: pavement: the default three-sided single tile
// The pigment alone (ambient 1, diffuse 0) on a plane and a sphere, seen at a slant, through a
// colour map whose entries are far apart, so any change of the pattern value shows.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at <0, 0.5, 0> angle 60 }
#declare P = pigment { pavement color_map { [0 rgb <0.1, 0, 0.4>] [0.3 rgb <0, 0.7, 0.2>] [0.6 rgb <1, 0.8, 0>] [1 rgb <1, 0.1, 0.1>] } scale 0.5 };
plane { y, 0 pigment { P } finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1 pigment { P } finish { ambient 1 diffuse 0 } }
