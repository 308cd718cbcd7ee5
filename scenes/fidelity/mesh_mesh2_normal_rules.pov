// povml fidelity scene: mesh_mesh2_normal_rules
// Rule: mesh2 normals without/with partial normal_indices (docs/povray-rules.md §2.6):
//       - no normal_indices and as many normal_vectors as vertex_vectors: face_indices are used as the
//         normal indices (left sheet: smooth);
//       - normal_indices with fewer entries than faces: only the first number_of_normal_indices faces
//         are smooth, the rest are flat (right sheet: faces 2 and 3 flat);
//       - a face whose three normals are the same is flat with the GEOMETRIC normal (right sheet,
//         face 1 uses normal 2, which is tilted to the right, three times).
// Two identical curved sheets (4 triangles each, bulging toward the camera). Left: smooth all over.
// Right: only its lower-left triangle (face 0) is smooth; the other three triangles are flat facets.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.21, 1.8, -5.6> look_at <0.04, 1.15, 0.4> right x*image_width/image_height angle 56 }
background { rgb <0.25, 0.25, 0.3> }
light_source { <-3.9, 4.4, -4.7>, rgb 1 }
#declare Tx = texture { pigment { rgb <0.9, 0.8, 0.55> } finish { diffuse 0.75 phong 0.6 phong_size 25 } }
mesh2 {
  vertex_vectors { 6,
    <-2.268, 0.285, 0.322>, <-1.39, 0.301, 0.0015>, <-0.5892, 0.316, 0.364>, <-2.268, 2.185, 0.322>, <-1.39, 2.201, 0.0015>, <-0.5892, 2.216, 0.364> }
  normal_vectors { 6,
    <-0.6816, 0, -0.7317>, <0.05, 0, -0.9988>, <0.7174, 0, -0.6967>, <-0.6816, 0, -0.7317>, <0.05, 0, -0.9988>, <0.7174, 0, -0.6967> }
  face_indices { 4, <0, 1, 4>, <0, 4, 3>, <1, 2, 5>, <1, 5, 4> }
  texture { Tx }
}
mesh2 {
  vertex_vectors { 6,
    <0.682, 0.285, 0.422>, <1.56, 0.301, 0.1015>, <2.3608, 0.316, 0.464>, <0.682, 2.185, 0.422>, <1.56, 2.201, 0.1015>, <2.3608, 2.216, 0.464> }
  normal_vectors { 3,
    <-0.6816, 0, -0.7317>, <0.05, 0, -0.9988>, <0.7174, 0, -0.6967> }
  face_indices { 4, <0, 1, 4>, <0, 4, 3>, <1, 2, 5>, <1, 5, 4> }
  normal_indices { 2, <0, 1, 1>, <2, 2, 2> }
  texture { Tx }
}
plane { y, 0 pigment { rgb <0.75, 0.78, 0.8> } }
