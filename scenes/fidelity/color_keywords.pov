// povml fidelity scene: color_keywords
// Rule: colour syntax: rgb/rgbf/rgbt/rgbft, optional `color`/`colour` keyword, component keywords
//       red/green/blue/filter/transmit overwrite components; `rgbt V` puts V's 4th term in TRANSMIT;
//       a float after rgb is replicated (docs/povray-rules.md §11.2).
// Left: color red 1 green 0.5 (blue stays 0). Second: rgb <0.2,0.4,1> filter 0.7 (filtered blue).
// Third: rgbt <1,1,0.3,0.6> (transmit). Right: color rgb 0.3 blue 0.9 transmit 0.3.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.3, 0.35> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.4, 0.8, 0>, 0.65 pigment { color red 1 green 0.5 } }
sphere { <-0.8, 0.8, 0>, 0.65 pigment { rgb <0.2, 0.4, 1> filter 0.7 } }
sphere { < 0.8, 0.8, 0>, 0.65 pigment { rgbt <1, 1, 0.3, 0.6> } }
sphere { < 2.4, 0.8, 0>, 0.65 pigment { color rgb 0.3 blue 0.9 transmit 0.3 } }
plane { z, 2 pigment { rgb <0.9, 0.4, 0.4> } }
plane { y, 0 pigment { rgbft <0.6, 0.6, 0.6, 0, 0> } }
