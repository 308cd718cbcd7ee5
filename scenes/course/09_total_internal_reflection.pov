// povml course scene 09 -- slide "Using Snell's Law", the note: "if the root is negative then total
// internal reflection has occurred and you just reflect the vector as normal".
// Shows: the camera is under water (plane y = 0 with ior 1.33; the camera starts "inside" it) and
// looks up. Rays meeting the surface steeper than the critical angle (48.8 degrees from the
// normal) refract out: "Snell's window", a disc showing the sky and the green ball above the
// water. Outside it 1 + eta^2 (cos^2 a - 1) < 0: total internal reflection turns the surface into
// a perfect mirror of the sand and the balls under water.
// (docs/povray-rules.md §6.2: TIR ray traced at full strength and added unfiltered; §6.4 interior list.)
// (A lone glass ball seen from outside never shows TIR: a ray that got in always gets out.)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, -1.5, -3> look_at <0, 0, -1.6> right x*image_width/image_height }
background { rgb <0.45, 0.65, 0.95> }
light_source { <2, 9, -4>, rgb 1 }
plane { y, 0 pigment { rgbf <0.85, 0.95, 1, 0.95> } finish { ambient 0 diffuse 0 } interior { ior 1.33 } }
plane { y, -3 pigment { rgb <0.85, 0.75, 0.45> } }
sphere { <-1.3, -1.5, 0.5>, 0.6 pigment { rgb <0.9, 0.25, 0.2> } finish { phong 0.5 } }
sphere { < 1.5, -2.2, 2.5>, 0.5 pigment { rgb <0.95, 0.8, 0.15> } finish { phong 0.5 } }
sphere { < 0.3, 1.8, 0.8>, 0.9 pigment { rgb <0.2, 0.75, 0.3> } finish { phong 0.5 } }
sphere { <-1.5, 3.0, 3.5>, 1.0 pigment { rgb <0.3, 0.4, 0.9> } finish { phong 0.5 } }
