// povml stiff scene: far_origin
// Stresses: absolute coordinates near 1e5. An ordinary little scene (floor, mirror ball, glass
// ball, a triangle, two meshes) with its camera and light is moved by <1e5, 1e5, -1e5>: every
// hit point, shadow ray and reflected ray now carries 1e5-sized coordinates, so depths are
// differences of large numbers (double precision still leaves about 1e-11 of them).
// What POV-Ray gets wrong here, and povml reproduces: a mesh stores its vertices AND each face's
// plane distance in single precision (§2.6; MESH_TRIANGLE's Distance is an SNGL), and floats are
// 1/128 apart at 1e5. The left (green) mesh, written with its vertices at their final place, has
// its corners snapped to that grid and its face planes moved by up to 4e-3: its 12-sided pyramid
// is visibly uneven, its edges do not quite meet, and the tiny sliver above its apex (corners
// 0.003 apart) collapses to a line and is never hit. The right (blue) mesh is written at the
// origin and moved with `translate`: it keeps a transform, its vertices stay exact, and it
// renders as it would near the origin.
// A correct image otherwise: the same picture as without the move, no speckles on the floor or
// the balls, shadows where they belong.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
#declare Off = <1e5, 1e5, -1e5>;
camera { location <0, 1.6, -4.5> look_at <0, 0.6, 0> right x*image_width/image_height angle 55 translate Off }
background { rgb <0.4, 0.6, 0.9> }
light_source { <3, 6, -4>, rgb 1 translate Off }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.6> } finish { phong 0.3 } translate Off }
sphere { <-0.3, 0.6, 0.8>, 0.6 pigment { rgb <0.8, 0.85, 0.9> } finish { ambient 0.05 diffuse 0.2 reflection 0.7 phong 0.8 } translate Off }
sphere { <0.9, 0.45, -0.4>, 0.45 pigment { rgbf <0.95, 0.98, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.8 } interior { ior 1.5 } translate Off }
triangle { <-2.2, 0, 1.5>, <-1.2, 0, 2>, <-1.8, 1.4, 1.7> pigment { rgb <0.9, 0.3, 0.2> } translate Off }
// a 12-sided pyramid of radius r about (cx, cz), its apex at height h
#macro Pyramid(C, R, H)
  #local I = 0;
  #while (I < 12)
    #local A0 = 2 * pi * I / 12;
    #local A1 = 2 * pi * (I + 1) / 12;
    triangle { C + <R * cos(A0), 0, R * sin(A0)>, C + <R * cos(A1), 0, R * sin(A1)>, C + <0, H, 0> }
    #local I = I + 1;
  #end
  // a sliver whose corners are within 0.003 of each other: collapses in single precision at 1e5
  triangle { C + <0, H + 0.02, 0>, C + <0.003, H + 0.021, 0>, C + <0.001, H + 0.023, 0> }
#end
mesh { Pyramid(Off + <-1.35, 0, -0.9>, 0.4, 0.9) pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.4 } }
mesh { Pyramid(<0, 0, 0>, 0.4, 0.9) pigment { rgb <0.3, 0.5, 0.9> } finish { phong 0.4 } translate Off + <1.9, 0, 0.6> }
