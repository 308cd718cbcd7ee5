// povml fidelity scene: torus_shadows
// Rule: torus { R, r } about the Y axis, intersected as POV-Ray's quartic with the thick-cylinder
//       pre-test and the 1e-4 world depth limit (docs/povray-rules.md §15.5, §15.6); every modifier is
//       composed into the torus's transform (§14.4), the normal maps by the inverse transpose
//       (§14.6). Tori cast shadows on the floor and on each other from two lights (§4); the
//       root elimination keeps a shadow ray from a torus's own surface from hitting it again.
// Two tori on a plane: one rotated and lying on its side, one non-uniformly scaled.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 3.2, -6> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
light_source { <5, 4, -6>, rgb 0.35 }
torus { 1, 0.35 rotate x*70 rotate y*-25 translate <-1.1, 1.35, 0.3>
        pigment { rgb <0.9, 0.5, 0.1> } finish { phong 0.6 } }
torus { 0.8, 0.3 scale <1.4, 0.6, 0.9> translate <1.2, 0.18, -0.2>
        pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.5 roughness 0.02 } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
