// povml fidelity scene: ovus_stiff
// Rule: the stiff cases of ovus.cpp: rays tangent to the seams where the joint meets the spheres
//       (an orthographic camera looking along the axis and across it), the joint's root kept only
//       within ROOT_TOLERANCE of the torus, and a top radius of 2·bottom or more, which POV-Ray
//       replaces by a sphere (with its warning); the camera inside an ovus.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0.8, -6> look_at <0, 0.8, 0> right 6*x*image_width/image_height up 6*y }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
ovus { 1, 0.6 translate <-1.8, 0, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
ovus { 0.6, 1.1 translate <0.3, 0.2, 0> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
ovus { 0.5, 1.0 translate <2.2, 0.3, 0> pigment { rgb <0.3, 0.5, 0.9> } }
ovus { 0.4, 0.39 rotate 90*x translate <0, -1.5, 0> pigment { rgb <0.9, 0.8, 0.3> } }
ovus { 4, 3 scale 3 translate <0, -2, 0> pigment { rgbf <1, 1, 1, 0.8> } hollow }
