// povml fidelity scene: mesh_flat_smooth_mix
// Rule: in a mesh, a triangle entry is flat; a smooth_triangle entry interpolates its normals, but if
//       its three normalised normals are equal it is treated as FLAT with the GEOMETRIC normal (not the
//       supplied one); zero-area triangles are dropped silently at parse time; a triangle with its own
//       texture uses it, the others use the mesh texture; vertices are single-precision floats
//       (docs/povray-rules.md §2.6, §13.16, §13.21).
// One mesh, left to right: a flat red triangle; a smooth green triangle with fanning normals; a
// yellow smooth_triangle whose three equal normals point up-left (it must shade exactly like a flat
// triangle facing the camera, not like a face turned toward the light); a grey triangle with no own
// texture (mesh texture); plus two zero-area triangles (repeated vertex; collinear vertices) that
// must leave no trace.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.27, 1.5, -6.3> look_at <0.1, 1.1, 0.5> right x*image_width/image_height angle 58 }
background { rgb <0.25, 0.28, 0.35> }
light_source { <-4.1, 5.3, -3.6>, rgb 1 }
// POV-Ray 3.7 only accepts a texture IDENTIFIER inside a mesh triangle: texture { Id }
#declare T_Red = texture { pigment { rgb <0.9, 0.3, 0.25> } finish { phong 0.5 phong_size 25 } }
#declare T_Green = texture { pigment { rgb <0.3, 0.85, 0.35> } finish { phong 0.8 phong_size 20 } }
#declare T_Yellow = texture { pigment { rgb <0.95, 0.85, 0.2> } finish { phong 0.5 phong_size 25 } }
#declare T_Magenta = texture { pigment { rgb <1, 0, 1> } }
mesh {
  triangle { <-3.1, 0.3, 0.5>, <-1.65, 0.25, 0.3>, <-2.4, 2.1, 0.9> texture { T_Red } }
  smooth_triangle { <-1.45, 0.3, 0.3>, <-0.9, -0.2, -1>, <0.05, 0.2, 0.25>, <0.8, -0.1, -1>, <-0.65, 2.2, 0.6>, <-0.1, 0.9, -0.7> texture { T_Green } }
  // equal normals <-0.6, 0.5, -1> (unnormalised): flat, geometric normal ~ -z is used instead
  smooth_triangle { <0.25, 0.25, 0.35>, <-0.6, 0.5, -1>, <1.75, 0.3, 0.45>, <-0.6, 0.5, -1>, <1.0, 2.15, 0.55>, <-0.6, 0.5, -1> texture { T_Yellow } }
  // no texture of its own: uses the mesh texture below
  triangle { <1.95, 0.35, 0.6>, <3.25, 0.3, 0.2>, <2.7, 1.95, 0.75> }
  // zero-area triangles: dropped
  triangle { <-1.0, 2.5, 0.2>, <-1.0, 2.5, 0.2>, <1.5, 2.9, 0.1> texture { T_Magenta } }
  triangle { <-2.5, 0.125, -0.5>, <0.5, 0.125, -0.5>, <2.5, 0.125, -0.5> texture { T_Magenta } }
  texture { pigment { rgb <0.6, 0.6, 0.65> } finish { diffuse 0.8 } }
}
plane { y, 0 pigment { rgb <0.8, 0.78, 0.72> } }
