// A checker plane whose pattern is scaled and rotated inside the pigment, one colour given
// (the second is the default green): docs/povray-rules.md §17.4, §17.1.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -8> look_at <0, 0, 0> }
light_source { <5, 10, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb <1, 0, 0> scale 1.5 rotate <0, 30, 0> } finish { ambient 0.2 diffuse 0.8 } }
sphere { <0, 1, 0>, 1 pigment { checker rgb <1, 1, 0>, rgb <0, 0, 1> scale 0.5 } finish { phong 0.6 } }
