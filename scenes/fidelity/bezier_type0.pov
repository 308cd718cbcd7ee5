// povml fidelity scene: bezier_type0
// Rule: bicubic_patch type 0 (bezier.cpp): subdivided for every ray (bezier_subdivider), the
//       same flatness rule; moved by rotate (MTransPoint of every control point), scale
//       (multiplied) and translate (added); seen from both sides.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.4,0.4,0.5> } }
bicubic_patch { type 0 flatness 0.02 u_steps 4 v_steps 2
  <-1.5, 0, -1.5>, <-0.5, 1, -1.5>, <0.5, -1, -1.5>, <1.5, 0, -1.5>,
  <-1.5, 0.5, -0.5>, <-0.5, 1.5, -0.5>, <0.5, 0.5, -0.5>, <1.5, 0, -0.5>,
  <-1.5, -0.5, 0.5>, <-0.5, 0, 0.5>, <0.5, 1.5, 0.5>, <1.5, 0.5, 0.5>,
  <-1.5, 0, 1.5>, <-0.5, -0.5, 1.5>, <0.5, 0.5, 1.5>, <1.5, 0, 1.5>
  rotate <20, 30, 0> scale <1, 0.7, 1.2> translate <0.2, 0, 0.3>
  pigment { rgb <0.3, 0.7, 1> } finish { specular 0.5 } }
