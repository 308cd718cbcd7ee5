// povml fidelity scene: refraction_glass
// Rule: Snell refraction with Heckbert's formula, ior ratio n_i/n_t from the interior list;
//       transmitted colour scaled by filCol = rgb*filter + transmit (docs/povray-rules.md §6.1, §6.2, §6.3).
// A glass ball (rgbf <0.9,1,0.9,0.95>, ior 1.5) in front of a row of coloured balls: they appear
// inverted and magnified inside it. Its shadow is filtered but not refracted (§4).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.3, -6> look_at <0, 1.0, 0> right x*image_width/image_height }
background { rgb <0.5, 0.6, 0.8> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <0, 1.08, -1.5>, 1.0 pigment { rgbf <0.9, 1, 0.9, 0.95> } finish { ambient 0 diffuse 0.1 phong 0.8 phong_size 120 } interior { ior 1.5 } }
sphere { <-1.2, 0.6, 2.0>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { < 0.0, 1.6, 2.2>, 0.5 pigment { rgb <0.2, 0.8, 0.2> } }
sphere { < 1.2, 0.6, 2.0>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } }
plane { y, 0 pigment { rgb <0.8, 0.7, 0.5> } }
plane { z, 5 pigment { rgb <0.9, 0.9, 0.6> } }
