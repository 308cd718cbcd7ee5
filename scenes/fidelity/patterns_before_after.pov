// povml fidelity scene: patterns_before_after
// Rule: a pigment attached before an object's transforms moves with the object, one attached
//       after them stays in world space (docs/povray-rules.md §14.7).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -7> look_at <0, 1, 0> right x*image_width/image_height }
light_source { <3, 9, -6> color rgb 1 }
box { <-1, -1, -1>, <1, 1, 1> pigment { checker rgb <1, 0.8, 0.1>, rgb <0.1, 0.3, 0.8> scale 0.5 }
  scale <0.8, 1.2, 0.6> rotate <20, 35, 10> translate <-1.6, 1.3, 0> }
box { <-1, -1, -1>, <1, 1, 1>
  scale <0.8, 1.2, 0.6> rotate <20, 35, 10> translate <1.6, 1.3, 0>
  pigment { checker rgb <1, 0.8, 0.1>, rgb <0.1, 0.3, 0.8> scale 0.5 } }
plane { y, 0 pigment { gradient z color_map { [0 rgb 0.9] [1 rgb 0.4] } } }
