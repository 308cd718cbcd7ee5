// povml course scene 04 -- slides "Introducing Reflection" and "Computing Reflectance".
// Shows: the reflected ray R = -E + 2(N.E)N (E pointing to the eye; POV-Ray writes it as
// D - 2(D.N)N with D = -E) is cast from the hit point and I = I_local + kr * I_r'.
// A mirror ball (kr = 0.8) and a slightly reflective floor (kr = 0.25) reflect the coloured balls.
// (docs/povray-rules.md §5.3.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.45, 0.7> }
light_source { <-4, 7, -4>, rgb 1 }
sphere { < 0.0, 1.1, 0.5>, 1.0 pigment { rgb 0.1 } finish { ambient 0 diffuse 0.2 reflection 0.8 phong 0.8 } }
sphere { <-2.3, 0.7, -0.5>, 0.6 pigment { rgb <0.9, 0.25, 0.2> } finish { phong 0.5 } }
sphere { < 2.2, 0.7, -0.2>, 0.6 pigment { rgb <0.25, 0.8, 0.3> } finish { phong 0.5 } }
sphere { < 0.8, 0.35, -1.8>, 0.3 pigment { rgb <0.9, 0.8, 0.2> } }
plane { y, 0 pigment { rgb <0.6, 0.6, 0.65> } finish { reflection 0.25 } }
