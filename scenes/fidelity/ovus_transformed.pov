// povml fidelity scene: ovus_transformed
// Rule: every modifier of an ovus composes into its Trans (Ovus::Transform); the ray enters
//       ovus space by the inverse, its direction renormalised, depths divided by that length;
//       the normals go out by the inverse transpose; the box is Compute_BBox's mapped.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
ovus { 1, 0.6 scale <0.8, 1.2, 0.5> rotate <20, 35, -30> translate <-2.2, 1.2, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
ovus { 0.6, 1 rotate 90*x translate <0, 1, 0.5> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
ovus { 0.8, 1.2 matrix <1, 0.3, 0, 0, 1, 0, 0.4, 0, 1, 0, 0, 0> scale 0.7 translate <2.2, 0.6, 0> pigment { rgb <0.3, 0.5, 0.9> } }
ovus { 0.5, 0.3 rotate 180*z translate <0, 1.3, -2.2> pigment { rgb <0.9, 0.8, 0.3> } }
