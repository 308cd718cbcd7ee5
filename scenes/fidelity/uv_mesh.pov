// povml fidelity scene: uv_mesh
// Rule: mesh triangles' uv_vectors blended by Mesh::UVCoord's weights (1 + t1/t2 per corner on
//       the single-precision vertices), the first two swapped with the corners when the set-up
//       swaps them; triangles without uv_vectors have (0, 0) at every corner. The mesh is moved.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
mesh {
  triangle { <-1, -1, 0>, <1, -1, 0>, <1, 1, 0> uv_vectors <0, 0>, <1, 0>, <1, 1> }
  triangle { <-1, -1, 0>, <1, 1, 0>, <-1, 1, 0> uv_vectors <0, 0>, <1, 1>, <0, 1> }
  smooth_triangle { <-1, 1, 0>, <0, 0.3, -1>, <1, 1, 0>, <0, 0.3, -1>, <0, 1.8, 0.5>, <0, 1, 0> uv_vectors <0, 1>, <1, 1>, <0.5, 1.6> }
  triangle { <1, -1, 0>, <2, -1, 0.5>, <1, 1, 0> }
  pigment { uv_mapping checker rgb <1, 0.3, 0.1> rgb <0.1, 0.3, 1> scale 0.125 }
  finish { ambient 0.15 diffuse 0.8 }
  rotate <10, -25, 5> translate <-0.4, -0.2, 0.5>
}
plane { y, -1.3 pigment { rgb 0.6 } }
