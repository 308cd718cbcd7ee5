// povml course scene 01 -- slides "Recap: Local Illumination" and "Recap: Result of Ray Casting".
// Shows: ray casting with local illumination only, I = ka*Ia + sum_j Ii,j * kd (n.l_j): every light
// is assumed visible (no shadow feelers), so there are no shadows at all.
// In POV-Ray terms the lights are `shadowless` (docs/povray-rules.md §3.2, §3.3); note that POV-Ray's
// shadowless lights also give no phong/specular highlights (§13.7).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.15, 0.2, 0.3> }
light_source { <-4, 7, -4>, rgb 0.9 shadowless }
light_source { < 5, 4, -2>, rgb 0.4 shadowless }
sphere { <-2.0, 1.0, 0.5>, 0.8 pigment { rgb <0.9, 0.25, 0.2> } finish { ambient 0.1 diffuse 0.7 specular 0.6 } }
sphere { < 0.0, 1.4, 1.0>, 0.8 pigment { rgb <0.25, 0.8, 0.3> } finish { ambient 0.1 diffuse 0.7 specular 0.6 } }
sphere { < 2.0, 1.0, 0.5>, 0.8 pigment { rgb <0.25, 0.35, 0.9> } finish { ambient 0.1 diffuse 0.7 specular 0.6 } }
sphere { < 0.3, 0.4, -1.5>, 0.3 pigment { rgb <0.9, 0.8, 0.2> } finish { ambient 0.1 diffuse 0.7 specular 0.6 } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
