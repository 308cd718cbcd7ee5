// povml fidelity scene: patterns_brick
// Rule: brick: mortar joints just below the multiples of the brick size, odd courses shifted by
//       half a brick; value 0 is the mortar (docs/povray-rules.md §17.7).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1, 2, -6> look_at <0, 1.2, 0> right x*image_width/image_height }
light_source { <-3, 6, -8> color rgb 1 }
box { <-3, 0, 0>, <3, 3, 0.5> pigment { brick rgb 0.8, rgb <0.7, 0.2, 0.1> brick_size <1.6, 0.6, 1> mortar 0.1 } }
box { <-3, 0, -4>, <3, 0.5, -1> pigment { brick brick_size <0.8, 0.3, 0.5> mortar 0.05 scale 1.2 } }
sphere { <2, 1, -2>, 0.8 pigment { brick rgb <0.1, 0.1, 0.5> mortar 0.2 scale 0.2 } }
plane { y, 0 pigment { rgb 0.5 } }
