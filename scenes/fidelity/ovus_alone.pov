// povml fidelity scene: ovus_alone
// Rule: ovus { B, T } (ovus.cpp) is a bottom sphere of radius B at the origin, a top sphere of
//       radius T at height B, and the inner part of a spindle torus joining them (Parse_Ovus's
//       two cases: B > T, and T ≥ B up to 2B); hits above EPSILON in ovus space; each part's
//       normal is the one stored with its hit. T ≥ 2B gives a sphere (POV-Ray's warning).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
ovus { 1, 0.6 translate <-2.4, 1, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
ovus { 0.6, 1 translate <0, 0.6, 0> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
ovus { 0.8, 0.8 translate <2.4, 0.8, 0> pigment { rgb <0.3, 0.5, 0.9> } }
ovus { 0.5, 0.95 sturm translate <-1.2, 0.5, 2.5> pigment { rgb <0.9, 0.8, 0.3> } }
ovus { 0.7, 0.2 translate <1.3, 0.7, 2.2> pigment { rgb <0.8, 0.5, 0.9> } finish { phong 0.4 } }
ovus { 0.3, 0.7 translate <0, 0.3, -2.3> pigment { rgb <0.5, 0.9, 0.9> } }
