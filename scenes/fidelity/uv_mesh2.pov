// povml fidelity scene: uv_mesh2
// Rule: mesh2's uv_vectors through uv_indices (left), or, without uv_indices, through the face
//       indices when there are as many UV vectors as vertices (right); a uv-mapped texture_list
//       texture on one face (parse.cpp Parse_Mesh2).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
#declare T2 = texture { pigment { uv_mapping gradient x color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 0.5, 0.2>] } scale 0.5 } }
mesh2 {
  vertex_vectors { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <0, 0, -0.6> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  texture_list { 1, texture { T2 } }
  face_indices { 4, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4>, 0 }
  uv_indices { 4, <0, 1, 2>, <1, 2, 3>, <2, 3, 0>, <3, 0, 1> }
  pigment { uv_mapping checker rgb <1, 0.3, 0.1> rgb <0.1, 0.3, 1> scale 0.1 }
  finish { ambient 0.15 diffuse 0.8 }
  rotate <0, 20, 0> translate <-1.2, 0, 0>
}
mesh2 {
  vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> }
  uv_vectors { 4, <0, 0>, <2, 0>, <2, 3>, <0, 3> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  pigment { uv_mapping checker rgb <1, 1, 0.2> rgb <0.2, 0.6, 0.2> scale 0.25 }
  finish { ambient 0.15 diffuse 0.8 }
  rotate <-20, -30, 0> translate <1.3, 0, 0>
}
plane { y, -1.3 pigment { rgb 0.6 } }
