// povml fidelity scene: superellipsoid_transformed
// Rule: every modifier of a superellipsoid composes into its Trans (Superellipsoid::Transform);
//       the ray enters its space by the inverse, its direction renormalised, and depths are
//       divided by that length; the normal goes out by the inverse transpose; the box is the
//       corners of ±1.0001 mapped (Recompute_BBox).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
superellipsoid { <0.3, 0.6> scale <1.2, 0.5, 0.7> rotate <20, 35, 10> translate <-2.2, 1, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
superellipsoid { <1.5, 0.4> rotate 90*x scale <0.6, 1.3, 0.6> translate <0, 1.3, 0.5> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
superellipsoid { <0.8, 2> matrix <1, 0.3, 0, 0, 1, 0, 0.4, 0, 1, 0, 0, 0> translate <2.2, 1, 0> pigment { rgb <0.3, 0.5, 0.9> } }
superellipsoid { <0.1, 0.1> scale 0.4 rotate <45, 45, 0> translate <0, 0.6, -2.2> pigment { rgb <0.9, 0.8, 0.3> } }
