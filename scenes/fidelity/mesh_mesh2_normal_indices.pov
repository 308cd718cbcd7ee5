// povml fidelity scene: mesh_mesh2_normal_indices
// Rule: mesh2 vertex_vectors / normal_vectors / face_indices / normal_indices: face i is smooth with the
//       normals normal_vectors[normal_indices[i]] (each normalised at parse time), interpolated as for
//       smooth_triangle; vertices and normals are single-precision floats, and the plane constant is
//       computed from the float vertices (docs/povray-rules.md §2.6, §2.5).
// A wavy vertical strip of 8 triangles (2 rows x 5 columns of vertices) with one normal per column.
// The 5 normals are listed in a shuffled order and there are fewer normals than vertices, so only
// normal_indices can pair them correctly; the strip shades smoothly with no creases at the
// triangle edges; light from the left puts a phong highlight on the left crest.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.33, 1.9, -5.8> look_at <0.05, 1.2, 0.4> right x*image_width/image_height angle 60 }
background { rgb <0.22, 0.25, 0.3> }
light_source { <-5.3, 2.9, -2.2>, rgb 1 }
mesh2 {
  vertex_vectors { 10,
    <-2.3, 0.258, 0.6621>, <-1.2, 0.302, 0.0511>, <-0.1, 0.346, 0.6026>, <1, 0.39, 0.8884>, <2.1, 0.434, 0.1684>,
    <-2.3, 2.319, 0.6621>, <-1.2, 2.286, 0.0511>, <-0.1, 2.253, 0.6026>, <1, 2.22, 0.8884>, <2.1, 2.187, 0.1684> }
  normal_vectors { 5,
    <-0.0529, 0, -1>, <-0.3862, 0, -1>, <-0.5172, 0, -1>, <-0.7137, 0, -1>, <0.7449, 0, -1> }
  face_indices { 8,
    <0, 1, 6>, <0, 6, 5>, <1, 2, 7>, <1, 7, 6>, <2, 3, 8>, <2, 8, 7>, <3, 4, 9>, <3, 9, 8> }
  normal_indices { 8,
    <3, 0, 0>, <3, 0, 3>, <0, 4, 4>, <0, 4, 0>, <4, 1, 1>, <4, 1, 4>, <1, 2, 2>, <1, 2, 1> }
  pigment { rgb <0.4, 0.6, 0.95> }
  finish { diffuse 0.75 phong 0.7 phong_size 12 }
}
plane { y, 0 pigment { rgb <0.8, 0.78, 0.7> } }
