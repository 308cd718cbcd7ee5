// povml course scene 02 -- slides "Correcting for Non-Visible Lights" and "Result of Shadow Feeler".
// Shows: I = ka*Ia + sum_j S_j Ii,j (kd (n.l_j) + ks (h_j.n)^n): a shadow feeler is cast from each
// hit point toward each light, and S_j = 0 if it hits an object first. Same scene as 01 with
// ordinary (shadow-casting) lights: shadows appear, and the specular highlights come back.
// (docs/povray-rules.md §4; specular §3.3.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.15, 0.2, 0.3> }
light_source { <-4, 7, -4>, rgb 0.9 }
light_source { < 5, 4, -2>, rgb 0.4 }
sphere { <-2.0, 1.0, 0.5>, 0.8 pigment { rgb <0.9, 0.25, 0.2> } finish { ambient 0.1 diffuse 0.7 specular 0.6 } }
sphere { < 0.0, 1.4, 1.0>, 0.8 pigment { rgb <0.25, 0.8, 0.3> } finish { ambient 0.1 diffuse 0.7 specular 0.6 } }
sphere { < 2.0, 1.0, 0.5>, 0.8 pigment { rgb <0.25, 0.35, 0.9> } finish { ambient 0.1 diffuse 0.7 specular 0.6 } }
sphere { < 0.3, 0.4, -1.5>, 0.3 pigment { rgb <0.9, 0.8, 0.2> } finish { ambient 0.1 diffuse 0.7 specular 0.6 } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
