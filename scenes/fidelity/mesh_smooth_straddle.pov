// povml fidelity scene: mesh_smooth_straddle
// Rule: a STANDALONE smooth_triangle whose vertex normals are not all on the same side of its
//       geometric normal is flagged degenerate and is INVISIBLE ("Degenerate triangle. Please remove.");
//       the same triangle inside a mesh is not subject to that rule and is drawn (docs/povray-rules.md §2.5,
//       §2.6, §13.16).
// Left: standalone smooth_triangle with straddling normals (N3 points behind the face): nothing is
// drawn, the backdrop and floor show through and it casts no shadow. Middle: the identical triangle
// (translated by <1.9,0,0>) as the only member of a mesh: visible, its shading swings where the
// interpolated normal turns past the view direction. Right: a standalone smooth_triangle with valid
// normals, drawn normally.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.31, 1.7, -5.9> look_at <0.15, 1.05, 0.2> right x*image_width/image_height angle 56 }
background { rgb <0.3, 0.3, 0.35> }
light_source { <-3.3, 5.1, -4.2>, rgb 1 }
#declare N1 = < 0.3, 0.2, -1>;
#declare N2 = <-0.2, 0.3, -1>;
#declare N3 = < 1.0, 0.05, 0.25>;
#declare Tx = texture { pigment { rgb <0.95, 0.75, 0.2> } finish { phong 0.5 phong_size 20 } }
// invisible
smooth_triangle { <-2.35, 0.3, 0.1>, N1, <-0.75, 0.35, 0.2>, N2, <-1.6, 1.95, 0.15>, N3 texture { Tx } }
// the same triangle in a mesh: visible
mesh {
  smooth_triangle { <-2.35, 0.3, 0.1> + <1.9, 0, 0>, N1, <-0.75, 0.35, 0.2> + <1.9, 0, 0>, N2, <-1.6, 1.95, 0.15> + <1.9, 0, 0>, N3 }
  texture { Tx }
}
// valid standalone smooth_triangle: visible
smooth_triangle { <1.45, 0.3, 0.1>, <-0.3, 0.2, -1>, <3.05, 0.35, 0.2>, <0.3, 0.1, -1>, <2.2, 1.95, 0.15>, <0.1, 0.6, -1> texture { Tx } }
plane { z, 1.7 pigment { rgb <0.35, 0.55, 0.8> } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
