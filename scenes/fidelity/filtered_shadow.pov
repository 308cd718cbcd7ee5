// povml fidelity scene: filtered_shadow
// Rule: a non-opaque object multiplies the light by (rgb*filter + transmit) at EVERY surface
//       crossing (twice for a closed sphere); shadows do not refract (docs/povray-rules.md §4, §3.5).
// Left: rgbf <1,0.2,0.2,0.8> (red-tinted shadow). Middle: rgbt <1,1,1,0.6> (grey shadow, 0.36).
// Right: rgbft <0.2,0.4,1,0.5,0.3> (blue-tinted shadow). Default ior 1, so the camera sees
// straight through them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.3, 0.5> right x*image_width/image_height }
background { rgb <0.2, 0.2, 0.25> }
light_source { <0, 8, -2>, rgb 1 }
sphere { <-2.0, 1.0, 0>, 0.7 pigment { rgbf <1, 0.2, 0.2, 0.8> } }
sphere { < 0.0, 1.0, 0>, 0.7 pigment { rgbt <1, 1, 1, 0.6> } }
sphere { < 2.0, 1.0, 0>, 0.7 pigment { rgbft <0.2, 0.4, 1, 0.5, 0.3> } }
plane { y, 0 pigment { rgb 0.9 } }
