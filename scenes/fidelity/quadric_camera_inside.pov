// povml fidelity scene: quadric_camera_inside
// Rule: the camera ray starts inside every top-level object whose box and Inside hold the camera
//       (docs/povray-rules.md §6.4): here an unbounded glass cylinder (its box is the huge box) and a
//       glass ellipsoid around the camera, and a glass quadric made inside-out by inverse (the
//       camera outside its surface is inside it). Each surface the ray leaves through refracts
//       by the right ratio only if the list was right.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1.2, -3> look_at <0, 0.8, 2> right x*image_width/image_height }
background { rgb <0.25, 0.35, 0.55> }
light_source { <-3, 6, -5>, rgb 1 }
// a vertical glass cylinder of radius 1.5 about the camera
quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 6>, 9 - 2.25
  pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.6 } interior { ior 1.3 } }
// a glass ellipsoid about the camera, radius 0.8 along x
quadric { <1.5625, 4, 4>, <0, 0, 0>, <0, -9.6, 24>, 5.76 + 36 - 1
  pigment { rgbf <1, 0.95, 0.9, 0.9> } finish { ambient 0 diffuse 0.05 } interior { ior 1.2 } }
// inside-out: everything outside the ball of radius 0.4 at <0.5, 0.9, 1>, glass of ior 1.1
quadric { <1, 1, 1>, <0, 0, 0>, <-1, -1.8, -2>, 0.25 + 0.81 + 1 - 0.16 inverse
  pigment { rgbf <0.95, 1, 0.95, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.5 } interior { ior 1.1 } }
box { <-2, 0, 3>, <-1, 2, 3.5> pigment { rgb <0.9, 0.2, 0.2> } }
box { <-0.5, 0, 3>, <0.5, 2, 3.5> pigment { rgb <0.2, 0.9, 0.2> } }
box { <1, 0, 3>, <2, 2, 3.5> pigment { rgb <0.2, 0.2, 0.9> } }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.5, 0.5, 0.5> } }
