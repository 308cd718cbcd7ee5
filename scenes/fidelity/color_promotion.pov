// povml fidelity scene: color_promotion
// Rule: a bare float or vector in a full colour context is promoted: `color 0.5` = rgbft
//       <0.5,0.5,0.5,0.5,0.5> (half filter, half transmit!), `color <r,g,b>` = opaque,
//       `color <r,g,b,f>` gives FILTER; `rgb 0.5` is opaque grey (docs/povray-rules.md §11.2, pitfall §13.17).
// Left to right: color 0.5 (see-through, att 0: only the transmitted part), rgb 0.5 (opaque),
// color <1,0.5,0.25,0.6> (filtered orange), color <0.2,0.6,0.9> (opaque blue).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.3, 0.35> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.4, 0.8, 0>, 0.65 pigment { color 0.5 } finish { phong 0.5 } }
sphere { <-0.8, 0.8, 0>, 0.65 pigment { rgb 0.5 } finish { phong 0.5 } }
sphere { < 0.8, 0.8, 0>, 0.65 pigment { color <1, 0.5, 0.25, 0.6> } finish { phong 0.5 } }
sphere { < 2.4, 0.8, 0>, 0.65 pigment { colour <0.2, 0.6, 0.9> } finish { phong 0.5 } }
plane { z, 2 pigment { rgb <0.9, 0.9, 0.2> } }
plane { y, 0 pigment { rgb <0.2, 0.6, 0.3> } }
