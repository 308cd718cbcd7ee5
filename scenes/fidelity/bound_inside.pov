// a ray that starts inside a bounding object meets the object even when it misses the bound's
// surface: the camera inside a bounding sphere, and shadow rays starting inside a bound
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -3> look_at <0, 0.5, 0> }
light_source { <2, 4, -3> rgb 1 }
union {
  plane { y, -1 pigment { checker rgb 0.2 rgb 0.8 } }
  sphere { <0, 0.3, 0>, 0.8 pigment { rgb <1, 0.5, 0.3> } }
  sphere { <1.2, 0.8, 0.5>, 0.4 pigment { rgb <0.3, 0.5, 1> } }
  bounded_by { sphere { <0, 1, -2>, 2.5 } }
}
