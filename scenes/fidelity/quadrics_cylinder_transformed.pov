// povml fidelity scene: quadrics_cylinder_transformed
// Rule: a cylinder's modifiers compose into its Trans after the canonical set-up (§14.4, §15.2):
//       rotate, non-uniform scale and a shearing matrix; the ray is moved into canonical space with
//       its direction renormalised and the depth divided by the length (§14.5 (b)); normals by the
//       inverse transpose (§14.6). Shadows fall on the floor and on each other (§4).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 4, -6.5> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-5, 9, -2>, rgb 1 }
light_source { <6, 5, -4>, rgb 0.35 }
cylinder { <0, 0, 0>, <0, 1, 0>, 1 scale <0.5, 1.5, 0.9> rotate <0, 30, 20> translate <-1.6, 0.3, 0.5>
  pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
cylinder { <0, 0, -1>, <0, 0, 1>, 0.4 rotate <30, 45, 0> scale <1.5, 0.7, 1> translate <0.8, 1.2, 0>
  pigment { rgb <0.3, 0.7, 0.9> } finish { specular 0.6 roughness 0.02 } }
cylinder { <-0.5, 0, 0>, <0.5, 0, 0>, 0.3 matrix <1, 0.3, 0, 0, 1, 0, 0.4, 0, 1, 0, 0, 0> translate <0.3, 0.3, -1.4>
  pigment { rgb <0.6, 0.9, 0.3> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
