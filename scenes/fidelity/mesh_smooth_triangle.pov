// povml fidelity scene: mesh_smooth_triangle
// Rule: smooth_triangle shading normal = normalize(w1 N1 + w2 N2 + w3 N3) with barycentric weights
//       (POV's u/v form N1 + u(N2 - N1 + v(N3 - N2))), vertex normals normalised at parse time
//       (docs/povray-rules.md §2.5); the interpolated normal is the one flipped toward the viewer (§3.1, §13.5).
// Two standalone smooth_triangles share a diagonal to form a flat quad with "pillow" normals
// (tilted outward at the corners, unnormalised on purpose): the diffuse shading varies across the flat
// face and a phong highlight sweeps across it; a third, separate smooth_triangle on the right has
// normals fanning from left to right. Both sides of the quad's diagonal match (no seam).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.23, 1.6, -5.7> look_at <0.1, 1.2, 0.4> right x*image_width/image_height angle 54 }
background { rgb <0.2, 0.22, 0.3> }
light_source { <-2.7, 4.3, -4.6>, rgb 1 }
#declare Pil = texture { pigment { rgb <0.85, 0.6, 0.3> } finish { diffuse 0.7 phong 0.9 phong_size 25 } }
// quad corners: A bottom-left, B bottom-right, C top-right, D top-left (nearly the plane z = 0.3)
#declare A = <-2.05, 0.2, 0.25>;
#declare B = < 0.95, 0.3, 0.35>;
#declare C = < 1.0, 2.45, 0.4>;
#declare D = <-1.95, 2.35, 0.3>;
#declare NA = <-0.8, -0.7, -1>;
#declare NB = < 0.8, -0.7, -1>;
#declare NC = < 1.6,  1.4, -2>;
#declare ND = <-0.8,  0.7, -1>;
smooth_triangle { A, NA, B, NB, C, NC texture { Pil } }
smooth_triangle { A, NA, C, NC, D, ND texture { Pil } }
// separate triangle on the right, normals fanning across it
smooth_triangle { <1.35, 0.35, 0.6>, <-0.9, 0.1, -1>, <2.75, 0.45, 0.9>, <0.9, 0.2, -1>, <2.1, 2.2, 0.8>, <0.05, 0.9, -0.6>
  pigment { rgb <0.3, 0.75, 0.9> } finish { phong 0.8 phong_size 15 } }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> } }
