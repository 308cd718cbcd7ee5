// povml fidelity scene: camera_under_plane
// Rule: primary rays start with every object whose Inside(camera) is true; for a plane the half
//       space OPPOSITE the normal is inside (n^.P - d < EPSILON) (docs/povray-rules.md §2.3, §6.4, §1.4).
// The camera is under a water surface plane { y, 0 } (ior 1.33): the first hit on it is an EXIT
// (ratio 1.33/1), giving Snell's window: the sky and the red ball are seen through a disc,
// outside which the surface totally reflects the sand and the green ball (§6.2).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, -1.5, -3> look_at <0, 0, -1.74> right x*image_width/image_height }
background { rgb <0.45, 0.65, 0.95> }
light_source { <2, 8, -3>, rgb 1 }
plane { y, 0 pigment { rgbf <0.8, 0.95, 1, 0.95> } finish { ambient 0 diffuse 0 } interior { ior 1.33 } }
plane { y, -3 pigment { rgb <0.85, 0.75, 0.45> } }
sphere { <0.5, 1.8, 2>, 1.0 pigment { rgb <0.9, 0.25, 0.2> } }
sphere { <-1.2, -1.8, 1.5>, 0.6 pigment { rgb <0.2, 0.8, 0.3> } }
