// povml benchmark scene: render at +W640 +H480 +A0.3.
// A few spheres (mirror, glass, coloured) and a reflective plane, two lights; exercises shadows,
// reflection, refraction and antialiasing. Subset only (docs/povray-rules.md §1-§9).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.4, -8> look_at <0, 1.0, 0> right x*image_width/image_height angle 55 }
background { rgb <0.35, 0.5, 0.8> }
light_source { <-5, 8, -6>, rgb 1 }
light_source { < 6, 6, -3>, rgb 0.4 }
sphere { <-2.2, 1.18, 0.5>, 1.1 pigment { rgb 0.15 } finish { ambient 0 diffuse 0.15 phong 0.9 phong_size 80 reflection 0.8 } }
sphere { <0.4, 1.08, -0.8>, 1.0 pigment { rgbf <0.95, 1, 0.95, 0.92> } finish { ambient 0 diffuse 0.05 phong 0.9 phong_size 150 reflection 0.05 } interior { ior 1.5 } }
sphere { <2.6, 0.88, 1.0>, 0.8 pigment { rgb <0.9, 0.25, 0.15> } finish { phong 0.6 } }
sphere { < 1.0, 0.45, 2.8>, 0.4 pigment { rgb <0.95, 0.8, 0.1> } finish { phong 0.6 } }
sphere { <-0.9, 0.35, -2.6>, 0.3 pigment { rgb <0.2, 0.45, 0.95> } finish { phong 0.6 } }
sphere { <-4.0, 0.65, 2.5>, 0.6 pigment { rgb <0.3, 0.85, 0.4> } finish { phong 0.6 reflection 0.1 } }
plane { y, 0 pigment { rgb <0.75, 0.72, 0.65> } finish { reflection 0.2 } }
