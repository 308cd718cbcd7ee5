// povml fidelity scene: mesh_triangle_shadow
// Rule: triangles and meshes are opaque shadow casters: a shadow ray toward the light is blocked by
//       any triangle hit with 1e-3 < t < dist - 1e-3 (docs/povray-rules.md §4, §2.1), using the same
//       dominant-axis edge test as camera rays (§2.4, §2.6); a mesh without inside_vector is an open
//       patch that still blocks light.
// A tilted standalone triangle over the floor throws a sharp triangular shadow that falls partly on
// a white ball; an open mesh "roof" of two triangles (a sloping quad, no inside_vector) shelters an
// orange ball, which sits in its shadow; a triangle lying almost flat a little above the floor
// (y 0.25..0.35) shows its own shadow offset beside it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.35, 3.4, -6.3> look_at <0.1, 0.6, 0.4> right x*image_width/image_height angle 56 }
background { rgb <0.4, 0.5, 0.65> }
light_source { <-2.6, 7.3, -2.9>, rgb 1 }
triangle { <-2.5, 1.3, 0.2>, <-0.8, 1.5, -0.2>, <-1.9, 2.4, 0.8>
  pigment { rgb <0.9, 0.35, 0.25> } finish { phong 0.4 } }
sphere { <-1.05, 0.45, 1.05>, 0.45 pigment { rgb <0.9, 0.9, 0.88> } }
mesh {
  triangle { <0.75, 1.05, -0.15>, <2.65, 1.1, -0.05>, <2.55, 1.55, 1.4> }
  triangle { <0.75, 1.05, -0.15>, <2.55, 1.55, 1.4>, <0.85, 1.5, 1.35> }
  pigment { rgb <0.3, 0.55, 0.9> }
  finish { phong 0.3 }
}
sphere { <1.65, 0.32, 0.75>, 0.32 pigment { rgb <0.95, 0.55, 0.1> } }
triangle { <-0.4, 0.25, -1.9>, <1.0, 0.35, -1.65>, <0.1, 0.3, -0.85>
  pigment { rgb <0.35, 0.8, 0.4> } }
plane { y, 0 pigment { rgb <0.85, 0.83, 0.78> } }
