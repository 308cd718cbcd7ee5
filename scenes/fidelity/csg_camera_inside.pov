// povml fidelity scene: csg_camera_inside
// Rule: the camera inside a glass merge starts inside its interior (§6.4: the top-level CSG's
//       Inside, its own interior); rays leaving it refract out (§6.2).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 1, -0.5> look_at <0, 1, 3> right x*image_width/image_height }
background { rgb <0.2, 0.25, 0.4> }
light_source { <-3, 6, -4>, rgb 1 }
merge {
  sphere { <0, 1, -0.3>, 1 }
  sphere { <0, 1, 0.8>, 0.8 }
  pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { ambient 0 diffuse 0 }
  interior { ior 1.3 }
}
box { <-3, 0, 4>, <-0.02, 3, 4.2> pigment { rgb <0.9, 0.3, 0.3> } }
box { <0.02, 0, 4>, <3, 3, 4.2> pigment { rgb <0.3, 0.9, 0.3> } }
sphere { <0.5, 0.5, 2.5>, 0.4 pigment { rgb <1, 1, 0.3> } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.8> } }
