// povml fidelity scene: patterns_filtered_map
// Rule: map colours keep filter and transmit and blend them like r, g, b; a map with a
//       transparent entry makes the object non-opaque, and shadow rays evaluate its pigment at
//       each crossing (docs/povray-rules.md §17.8, §3.5, §4).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 1, 0> right x*image_width/image_height }
light_source { <2, 8, -3> color rgb 1 }
light_source { <-4, 5, -5> color rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.6 } }
sphere { <0, 1.2, 0>, 1.2
  pigment { gradient y
    color_map { [0 rgbt <1, 0.2, 0.2, 0.7>] [0.4 rgbf <0.2, 1, 0.2, 0.9>] [0.6 rgb <0.2, 0.2, 1>] [1 rgbft <1, 1, 0, 0.5, 0.3>] }
    frequency 2 phase 0.1 translate <0, 0.2, 0> }
  finish { phong 0.8 } }
box { <1.8, 0, -1>, <2.8, 2, 0> pigment { checker rgbt <1, 0.5, 0, 0.8>, rgb <0, 0.4, 0.8> scale 0.5 } }
