// Planes (§2.3, §14.4, §14.5 a): rotated, scaled non-uniformly (baked), and one under a matrix
// (a Trans: ray unnormalised, limits in world units), each seen from above the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> right x*image_width/image_height angle 60 }
background { rgb <0.2, 0.22, 0.3> }
light_source { <-3, 6, -5>, rgb 1 }
plane { y, 0
  pigment { rgb <0.7, 0.7, 0.65> } finish { phong 0.3 }
  rotate <0, 0, 8>
  scale <1, 2, 0.5>
}
plane { <0, 0, -1>, -4
  pigment { rgb <0.5, 0.6, 0.9> } finish { phong 0.5 }
  rotate <15, 25, 0>
  translate <0, 0, 1>
}
plane { x, 3
  pigment { rgb <0.9, 0.4, 0.3> }
  matrix <1, 0.2, 0, 0.3, 1, 0.1, 0, 0.4, 1, 0.5, 0, 0>
  rotate <0, 0, -10>
}
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.9, 0.3> } finish { phong 0.6 } }
