// povml fidelity scene: torus_scaled_mirror
// Rule: a negative scale mirrors the torus: its transform has a negative determinant, the ray
//       is brought into torus space and renormalised, depths divided by the length (§14.5 (b)),
//       and the inverse-transpose normal stays outward (§14.6). scale <1,-1.5,.8> after a
//       rotation, compared with the same torus unmirrored.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -5>, rgb 1 }
light_source { <4, 2, -6>, rgb 0.3 }
torus { 0.9, 0.3 rotate <60, 20, 0> scale <1, -1.5, .8> translate <-1.2, 1.2, 0>
        pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.7 } }
torus { 0.9, 0.3 rotate <60, 20, 0> scale <1, 1.5, .8> translate <1.2, 1.2, 0>
        pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.7 } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
