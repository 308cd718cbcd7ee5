// povml fidelity scene: quadrics_cylinder_phong
// Rule: cylinder { P1, P2, r } closed by default: the canonical cylinder x²+y² = 1, 0 ≤ z ≤ 1
//       with P2 at z = 0 (docs/povray-rules.md §15.2), side and cap normals through the inverse
//       transpose (§14.6), phong highlights (§3.3), shadows on the floor (§4).
// A vertical and a lying closed cylinder, and a thin one leaning against them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1.5, 3.2, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
light_source { <5, 4, -6>, rgb 0.3 }
cylinder { <-1, 0, 0>, <-1, 1.6, 0>, 0.6 pigment { rgb <0.9, 0.5, 0.1> } finish { phong 0.8 phong_size 30 } }
cylinder { <0.3, 0.4, -0.5>, <1.8, 0.4, 0.6>, 0.4 pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.5 } }
cylinder { <-0.3, 0, -1.2>, <0.4, 1.5, 0.3>, 0.08 pigment { rgb <0.4, 0.5, 0.9> } finish { phong 1 phong_size 80 } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
