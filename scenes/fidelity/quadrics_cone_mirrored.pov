// povml fidelity scene: quadrics_cone_mirrored
// Rule: a negative scale mirrors a cone (scale <-1, 1.3, 1>, §14.2, §14.8); the inverse transpose
//       keeps its normals outward (§14.6); a mirrored cylinder and disc too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 3, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
light_source { <5, 4, -6>, rgb 0.3 }
cone { <0.5, 0, 0>, 0.7, <1, 1.2, 0.3>, 0.2 scale <-1, 1.3, 1> pigment { rgb <0.9, 0.5, 0.1> } finish { phong 0.7 } }
cylinder { <0.6, 0.3, -0.5>, <1.8, 0.5, 0.4>, 0.3 scale <1, -1, 1> translate <0, 1.2, 0> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.5 } }
disc { <0.8, 1.5, -1>, <0.3, 1, -0.5>, 0.5, 0.2 scale <1, 1, -1> translate <0, 0, -1.5> pigment { rgb <0.4, 0.5, 0.9> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
