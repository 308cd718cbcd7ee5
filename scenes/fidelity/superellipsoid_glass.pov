// povml fidelity scene: superellipsoid_glass
// Rule: refraction through a superellipsoid needs its inside rule and its normal from both
//       sides: the ray inside finds the far wall, starting beyond 1e-4 (DEPTH_TOLERANCE).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
superellipsoid { <0.3, 0.3> scale <1, 0.8, 0.6> rotate 25*y translate <-1.2, 0.9, 0>
  pigment { rgbf <0.95, 0.95, 1, 0.9> } finish { phong 0.9 reflection 0.1 } interior { ior 1.5 } }
superellipsoid { <1.8, 0.6> scale 0.8 translate <1.4, 0.9, 0.5>
  pigment { rgbf <1, 0.9, 0.8, 0.85> } finish { specular 0.6 } interior { ior 1.33 } }
sphere { <0, 0.4, 2.5>, 0.4 pigment { rgb <0.9, 0.3, 0.2> } }
