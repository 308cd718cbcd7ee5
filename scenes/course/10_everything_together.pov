// povml course scene 10 -- slides "Recursive Ray Tracing Including Transparent Objects",
// "New Pseudo Code" and "Putting Everything Together".
// Shows: local illumination + shadow feelers + reflection + refraction, recursively:
// I = I_local + kr I(R) + kt I(T). A mirror ball, a glass ball (with filtered shadow), a matte
// ball and a glossy reflective floor, lit by two lights. (docs/povray-rules.md, Appendix B.)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0.5, 2.4, -7> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.4, 0.55, 0.8> }
light_source { <-5, 8, -5>, rgb 0.9 }
light_source { < 6, 5, -3>, rgb <0.45, 0.4, 0.35> }
sphere { <-1.9, 1.08, 0.6>, 1.0 pigment { rgb 0.1 } finish { ambient 0 diffuse 0.15 reflection 0.85 phong 0.9 phong_size 80 } }
sphere { <0.6, 0.98, -1.0>, 0.9 pigment { rgbf <0.95, 1, 0.95, 0.92> } finish { ambient 0 diffuse 0.05 phong 0.9 phong_size 150 reflection 0.06 } interior { ior 1.5 } }
sphere { <2.3, 0.88, 1.2>, 0.8 pigment { rgb <0.9, 0.3, 0.15> } finish { ambient 0.1 diffuse 0.7 specular 0.4 } }
sphere { <-0.3, 0.4, 2.4>, 0.35 pigment { rgb <0.2, 0.5, 0.9> } }
plane { y, 0 pigment { rgb <0.75, 0.72, 0.6> } finish { diffuse 0.7 reflection 0.15 } }
