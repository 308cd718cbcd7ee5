// Meshes (§2.6, §14.4): a smooth octahedron rotated and scaled non-uniformly, a flat one moved
// and sheared; the ray goes to mesh space with a renormalised direction.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
background { rgb <0.2, 0.22, 0.3> }
light_source { <-3, 5, -4>, rgb 1 }
mesh {
  smooth_triangle { <1,0,0>, <1,0,0>, <0,1,0>, <0,1,0>, <0,0,1>, <0,0,1> }
  smooth_triangle { <0,0,1>, <0,0,1>, <0,1,0>, <0,1,0>, <-1,0,0>, <-1,0,0> }
  smooth_triangle { <-1,0,0>, <-1,0,0>, <0,1,0>, <0,1,0>, <0,0,-1>, <0,0,-1> }
  smooth_triangle { <0,0,-1>, <0,0,-1>, <0,1,0>, <0,1,0>, <1,0,0>, <1,0,0> }
  smooth_triangle { <1,0,0>, <1,0,0>, <0,-1,0>, <0,-1,0>, <0,0,1>, <0,0,1> }
  smooth_triangle { <0,0,1>, <0,0,1>, <0,-1,0>, <0,-1,0>, <-1,0,0>, <-1,0,0> }
  smooth_triangle { <-1,0,0>, <-1,0,0>, <0,-1,0>, <0,-1,0>, <0,0,-1>, <0,0,-1> }
  smooth_triangle { <0,0,-1>, <0,0,-1>, <0,-1,0>, <0,-1,0>, <1,0,0>, <1,0,0> }
  pigment { rgb <0.9, 0.5, 0.3> } finish { phong 0.8 phong_size 30 }
  rotate <20, 35, 10>
  scale <1.3, 0.8, 1>
  translate <-1.2, 1, 0>
}
mesh {
  triangle { <1,0,0>, <0,1,0>, <0,0,1> }
  triangle { <0,0,1>, <0,1,0>, <-1,0,0> }
  triangle { <-1,0,0>, <0,1,0>, <0,0,-1> }
  triangle { <0,0,-1>, <0,1,0>, <1,0,0> }
  triangle { <1,0,0>, <0,-1,0>, <0,0,1> }
  triangle { <0,0,1>, <0,-1,0>, <-1,0,0> }
  triangle { <-1,0,0>, <0,-1,0>, <0,0,-1> }
  triangle { <0,0,-1>, <0,-1,0>, <1,0,0> }
  inside_vector y
  pigment { rgb <0.3, 0.8, 0.5> } finish { specular 0.6 roughness 0.02 }
  scale 0.9
  matrix <1, 0.3, 0, 0, 1, 0, 0.2, 0, 1, 0, 0, 0>
  rotate <0, -25, 0>
  translate <1.4, 1, 0.3>
}
plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> } }
