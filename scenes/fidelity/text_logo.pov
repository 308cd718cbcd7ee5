// the crystal and povlogo fonts, an offset between letters, a matrix shear, mirrored text
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -6> look_at <0, 0.6, 0> angle 45 }
light_source { <3, 8, -9>, rgb 1 }
plane { y, -0.6 pigment { rgb <0.6, 0.62, 0.7> } finish { reflection 0.2 } }
text { ttf "crystal.ttf" "Crystal 42", 0.25, <0.05, 0.03, 0> translate <-2.4, 1.4, 0> pigment { rgb <0.9, 0.8, 0.2> } }
text { ttf "povlogo.ttf" "P", 0.4, 0 scale 1.5 translate <-2.3, -0.5, 0.3> pigment { rgb <0.3, 0.5, 0.95> } }
text { ttf "cyrvetic.ttf" "Shear", 0.3, 0 matrix <1, 0, 0, 0.4, 1, 0, 0, 0, 1, 0, 0, 0> translate <-0.6, -0.4, -0.5> pigment { rgb <0.9, 0.4, 0.6> } }
text { ttf "timrom.ttf" "Mirror", 0.3, 0 scale <-1, 1, 1> translate <2.6, 0.3, 0.5> pigment { rgb <0.4, 0.85, 0.8> } }
