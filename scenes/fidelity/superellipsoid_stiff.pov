// povml fidelity scene: superellipsoid_stiff
// Rule: the stiff cases of super.cpp's search: rays running in the cutting planes (the camera
//       on x = y and z = 0 in superellipsoid space), near-box and near-octahedron exponents
//       (e, n = 0.02 and 1.9: powers 100 and about 1.05), grazing rays along flat faces, and the
//       camera inside one (its first sample inside, the hit at the far wall); check_hit2's
//       secant steps find rays that dip into a piece without a sign change at its ends.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
superellipsoid { <0.02, 0.02> translate <-2.2, 1, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
superellipsoid { <1.9, 1.9> translate <0, 1, 0> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
superellipsoid { <3, 3> scale 0.9 translate <2.2, 1, 0> pigment { rgb <0.3, 0.5, 0.9> } }
superellipsoid { <0.5, 0.02> rotate 45*z translate <-1.1, -1.2, 0> pigment { rgb <0.9, 0.8, 0.3> } }
superellipsoid { <0.02, 0.5> scale <1, 0.3, 1> translate <1.1, -1.2, -0.5> pigment { rgb <0.8, 0.5, 0.9> } }
superellipsoid { <1, 1> scale 20 pigment { rgbf <1, 1, 1, 0.7> } interior { ior 1.0 } hollow }
plane { y, -2.5 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
