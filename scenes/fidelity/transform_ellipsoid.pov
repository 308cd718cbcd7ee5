// Ellipsoids (§2.2, §14.4, §14.5 b): a sphere scaled non-uniformly, then sheared by a matrix and
// moved; a second one rotated after the scale; a uniformly scaled sphere stays a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
background { rgb <0.2, 0.22, 0.3> }
light_source { <-3, 5, -4>, rgb 1 }
light_source { <4, 3, -2>, rgb <0.4, 0.35, 0.3> }
sphere { <0, 0, 0>, 1
  pigment { rgb <0.9, 0.5, 0.3> } finish { phong 0.8 phong_size 30 }
  scale <1, 0.5, 0.7>
  matrix <1, 0.4, 0, 0, 1, 0, 0.3, 0, 1, 0, 0, 0>
  translate <-1.2, 0.8, 0>
}
sphere { <0.3, 0.2, 0>, 0.8
  pigment { rgb <0.3, 0.8, 0.5> } finish { specular 0.6 roughness 0.02 }
  scale <0.6, 1.4, 0.9>
  rotate <20, 35, 10>
  translate <1.4, 1, 0.5>
}
sphere { <0, 0, 0>, 0.5
  pigment { rgb <0.5, 0.5, 0.9> } finish { phong 0.5 }
  scale -0.8
  rotate <0, 0, 30>
  translate <0, 0.4, -1.5>
}
plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> } }
