// povml fidelity scene: mesh_mesh2_texture_list
// Rule: mesh2 texture_list { n, texture{...} ... } with a texture index after a face in face_indices
//       (<a,b,c>, t) gives that face texture t of the list; a face without an index uses the
//       mesh's own texture; flat faces use the geometric normal (docs/povray-rules.md §2.6, §2.4).
// A folded panel of 12 flat triangles leaning back, faces coloured red / green / blue from a
// 3-entry texture_list (blue is shiny), two faces without an index in the mesh's grey texture.
// The four columns of faces are tilted differently, so each face has its own flat shade.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.41, 2.6, -5.6> look_at <0.1, 1.1, 0.5> right x*image_width/image_height angle 58 }
background { rgb <0.2, 0.2, 0.25> }
light_source { <-3.7, 5.8, -4.9>, rgb 1 }
mesh2 {
  vertex_vectors { 12,
    <-2.2, 0.3, -0.2>, <-0.75, 0.33, 0.15>, <0.7, 0.36, -0.3>, <2.15, 0.39, 0.1>,
    <-2.2, 1.25, 0.45>, <-0.75, 1.28, 0.8>, <0.7, 1.31, 0.35>, <2.15, 1.34, 0.75>,
    <-2.2, 2.2, 0.9>, <-0.75, 2.23, 1.25>, <0.7, 2.26, 0.8>, <2.15, 2.29, 1.2> }
  texture_list { 3,
    texture { pigment { rgb <0.9, 0.25, 0.2> } }
    texture { pigment { rgb <0.25, 0.8, 0.3> } finish { diffuse 0.8 } }
    texture { pigment { rgb <0.25, 0.35, 0.95> } finish { phong 0.6 phong_size 40 } } }
  face_indices { 12,
    <0, 1, 5>, 0, <0, 5, 4>, 1, <1, 2, 6>, 2, <1, 6, 5>, <2, 3, 7>, 1, <2, 7, 6>, 2,
    <4, 5, 9>, 0, <4, 9, 8>, 1, <5, 6, 10>, <5, 10, 9>, 0, <6, 7, 11>, 2, <6, 11, 10>, 1 }
  texture { pigment { rgb <0.7, 0.7, 0.7> } }
}
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
