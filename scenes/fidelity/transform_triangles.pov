// Triangles and smooth triangles (§2.4, §2.5, §14.4): corners (and normals by MTransNormal) baked,
// the set-up recomputed after each modifier.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.2, 1.6, -5.7> look_at <0.1, 1.1, 0.4> right x*image_width/image_height angle 54 }
background { rgb <0.2, 0.22, 0.3> }
light_source { <-2.7, 4.3, -4.6>, rgb 1 }
triangle { <-1, 0, 0>, <1, 0, 0>, <0, 1.5, 0.3>
  pigment { rgb <0.9, 0.5, 0.3> } finish { phong 0.7 }
  rotate <10, 40, 20>
  scale <1.2, 0.9, 1>
  translate <-1.4, 0.3, 0>
}
smooth_triangle { <-1, 0, 0>, <-0.8, -0.7, -1>, <1, 0, 0>, <0.8, -0.7, -1>, <0, 1.6, 0>, <0.1, 0.9, -0.6>
  pigment { rgb <0.3, 0.75, 0.9> } finish { phong 0.8 phong_size 15 }
  rotate <-20, 30, 15>
  scale <1, 1.3, 0.8>
  matrix <1, 0, 0, 0.25, 1, 0, 0, 0, 1, 0, 0, 0>
  translate <1.3, 0.4, 0.5>
}
smooth_triangle { <-1, 0, 0>, <-0.5, 0, -1>, <1, 0, 0>, <0.5, 0, -1>, <0, 1, 0.2>, <0, 0.5, -1>
  pigment { rgb <0.8, 0.8, 0.3> } finish { specular 0.5 }
  rotate <0, 180, 0>
  rotate <30, 0, 0>
  translate <0, 1.8, 1>
}
plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> } }
