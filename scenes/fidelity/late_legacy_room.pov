// Written after the code: a version-less (legacy) scene, gamma off, with planes as walls,
// the legacy transparency formula, a legacy glass finish, and no background statement.
camera { location <0, 1.5, -4> look_at <0, 1, 0> }
light_source { <1, 2.8, -2>, color rgb <1, 1, 0.9> }
light_source { <-1.5, 2, 1>, color 0.4 shadowless }
plane { y, 0 pigment { color rgb <0.6, 0.5, 0.4> } }
plane { -y, -3 pigment { color rgb 0.9 } }
plane { x, -2.5 pigment { color rgb <0.8, 0.3, 0.3> } }
plane { -x, -2.5 pigment { color rgb <0.3, 0.3, 0.8> } }
plane { -z, -3 pigment { color rgb 0.7 } finish { reflection 0.4 } }
sphere { <-0.8, 0.6, 0.5>, 0.6 pigment { color rgbf <0.9, 0.9, 1, 0.8> } finish { refraction 1 ior 1.5 phong 0.9 } }
sphere { <0.9, 0.5, 0.2>, 0.5 pigment { color rgbft <0.9, 0.7, 0.1, 0.3, 0.2> } finish { phong 0.5 } }
sphere { <0.2, 2.2, 1.5>, 0.3 pigment { color 0.5 } }
