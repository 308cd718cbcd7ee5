// povml course scene 08 -- slides "Perfect Specular Transmission" and "Using Snell's Law".
// Shows: sin(a)/sin(b) = eta2/eta1; the transmitted ray T = -eta12 E + N(eta12 cos a - sqrt(1 +
// eta12^2 (cos^2 a - 1))) is cast at each glass surface (entering and leaving), and
// I = I_local + kr I_r + kt I_t. A glass ball (ior 1.5) inverts the balls behind it; a water
// ball (ior 1.33) bends less. (docs/povray-rules.md §6.2, §6.3.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.6, -7> look_at <0, 1.0, 0> right x*image_width/image_height }
background { rgb <0.45, 0.6, 0.85> }
light_source { <-3, 7, -5>, rgb 1 }
sphere { <-1.3, 1.1, -1.0>, 1.0 pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { ambient 0 diffuse 0.05 phong 0.9 phong_size 150 } interior { ior 1.5 } }
sphere { < 1.3, 1.1, -1.0>, 1.0 pigment { rgbf <0.9, 0.95, 1, 0.95> } finish { ambient 0 diffuse 0.05 phong 0.9 phong_size 150 } interior { ior 1.33 } }
sphere { <-2.2, 0.58, 2.5>, 0.5 pigment { rgb <0.9, 0.2, 0.15> } }
sphere { <-0.6, 1.5, 3.0>, 0.5 pigment { rgb <0.9, 0.8, 0.2> } }
sphere { <0.8, 0.58, 2.5>, 0.5 pigment { rgb <0.2, 0.8, 0.3> } }
sphere { < 2.3, 1.4, 3.0>, 0.5 pigment { rgb <0.25, 0.35, 0.9> } }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.55> } }
plane { z, 6 pigment { rgb <0.85, 0.85, 0.9> } }
