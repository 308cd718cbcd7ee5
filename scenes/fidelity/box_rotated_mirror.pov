// povml fidelity scene: box_rotated_mirror
// Rule: a box under rotate and a non-uniform scale gets a transform (§14.4); its ray is brought
//       into object space unnormalised, so the depth limits apply to world depths (§14.5 (a)),
//       and the normal of the side hit goes through the inverse transpose and is normalised
//       (§14.6, §15.1). Reflection (§5) shows its faces again in a mirror box behind it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-3, 7, -4>, rgb 1 }
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> scale <1.6, 0.8, 1.1> rotate <15, 35, -10> translate <-0.6, 1.1, 0>
      pigment { rgb <0.9, 0.6, 0.2> } finish { phong 0.7 reflection 0.25 } }
box { <-3, 0, 2>, <3, 3, 2.3> rotate y*-12 pigment { rgb 0.1 } finish { ambient 0 diffuse 0.1 reflection 0.8 } }
box { <0, 0, 0>, <1, 1, 1> scale 0.6 rotate <0, 45, 0> translate <1.4, 0, -1> pigment { rgb <0.3, 0.7, 0.9> } finish { reflection 0.3 } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } finish { reflection 0.1 } }
