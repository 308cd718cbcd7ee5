// povml fidelity scene: mesh_mesh2_declared_twice
// Rule: a #declared mesh2 placed with object { M translate <...> } twice: both copies share the same
//       triangles and texture; translate moves the mesh (rays go to object space, the smooth normal
//       is computed there and transformed back), shadows and shading follow the moved copies
//       (docs/povray-rules.md §2.6, §14.4, §14.5, §14.6).
// A smooth hexagonal bipyramid (8 vertices, 12 faces, one normal per vertex, explicit
// normal_indices) declared at the origin, instanced at two places: two identical rounded "gems"
// whose highlights and shading differ only because their positions relative to the light and the
// camera differ. Each casts a shadow on the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.29, 2.3, -5.4> look_at <0.07, 0.95, 0.5> right x*image_width/image_height angle 55 }
background { rgb <0.3, 0.35, 0.45> }
light_source { <-2.9, 5.7, -3.8>, rgb 1 }
#declare Gem = mesh2 {
  vertex_vectors { 8,
    <0, 1, 0>, <0.6687, 0, 0.2069>, <0.1552, 0, 0.6826>, <-0.5135, 0, 0.4757>, <-0.6687, 0, -0.2069>, <-0.1552, 0, -0.6826>, <0.5135, 0, -0.4757>, <0, -1, 0> }
  normal_vectors { 8,
    <0, 1, 0>, <0.9553, 0, 0.2955>, <0.2217, 0, 0.9751>, <-0.7336, 0, 0.6796>, <-0.9553, 0, -0.2955>, <-0.2217, 0, -0.9751>, <0.7336, 0, -0.6796>, <0, -1, 0> }
  face_indices { 12,
    <0, 1, 2>, <7, 1, 2>, <0, 2, 3>, <7, 2, 3>, <0, 3, 4>, <7, 3, 4>, <0, 4, 5>, <7, 4, 5>, <0, 5, 6>, <7, 5, 6>, <0, 6, 1>, <7, 6, 1> }
  normal_indices { 12,
    <0, 1, 2>, <7, 1, 2>, <0, 2, 3>, <7, 2, 3>, <0, 3, 4>, <7, 3, 4>, <0, 4, 5>, <7, 4, 5>, <0, 5, 6>, <7, 5, 6>, <0, 6, 1>, <7, 6, 1> }
  pigment { rgb <0.85, 0.3, 0.6> }
  finish { phong 0.7 phong_size 40 }
}
object { Gem translate <-1.25, 1.08, 0.35> }
object { Gem translate < 1.35, 1.12, 0.9> }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.72> } }
