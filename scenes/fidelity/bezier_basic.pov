// povml fidelity scene: bezier_basic
// Rule: bicubic_patch type 1 (bezier.cpp): the subdivision kept as a tree of bounding spheres
//       (flatness 0.05, u_steps 3, v_steps 3), each leaf crossed as two triangles, the normal
//       interpolated from the patch's normals at the triangle's corners.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.4,0.4,0.5> } }
bicubic_patch { type 1 flatness 0.05 u_steps 3 v_steps 3
  <-1.5, 0, -1.5>, <-0.5, 1, -1.5>, <0.5, -1, -1.5>, <1.5, 0, -1.5>,
  <-1.5, 0.5, -0.5>, <-0.5, 1.5, -0.5>, <0.5, 0.5, -0.5>, <1.5, 0, -0.5>,
  <-1.5, -0.5, 0.5>, <-0.5, 0, 0.5>, <0.5, 1.5, 0.5>, <1.5, 0.5, 0.5>,
  <-1.5, 0, 1.5>, <-0.5, -0.5, 1.5>, <0.5, 0.5, 1.5>, <1.5, 0, 1.5>
  pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.5 } }
