// povml fidelity scene: superellipsoid_shadow
// Rule: shadow rays test a superellipsoid alone (its first hit only) between the point and the
//       light; the shadows of a rounded box and of a star fall on the floor and on a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 8, -2>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
superellipsoid { <0.2, 0.4> scale 0.7 translate <-1.2, 1.6, 0> pigment { rgb <0.9, 0.3, 0.2> } }
superellipsoid { <2.5, 2.5> scale 0.8 translate <1.2, 1.8, 0.5> pigment { rgb <0.3, 0.5, 0.9> } }
sphere { <1.5, 0.5, 0.8>, 0.5 pigment { rgb <0.3, 0.8, 0.4> } }
