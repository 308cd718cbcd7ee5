// text in two fonts (cyrvetic.ttf, timrom.ttf), moved, turned and scaled, casting shadows
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1.5, 2.2, -5> look_at <1.6, 0.4, 0> angle 50 }
light_source { <-6, 9, -8>, rgb 1 }
light_source { <7, 4, -3>, rgb 0.4 }
plane { y, -0.5 pigment { checker rgb <0.9, 0.9, 0.85> rgb <0.55, 0.6, 0.65> } }
plane { z, 1.5 pigment { rgb <0.7, 0.75, 0.8> } }
text { ttf "cyrvetic.ttf" "Ray 1.0 (WAVE)", 0.3, 0 pigment { rgb <0.9, 0.35, 0.2> } finish { phong 0.6 } translate <-0.6, 0.6, 0> }
text { ttf "timrom.ttf" "AWAY To Ty", 0.5, <0.02, 0, 0> scale <0.9, 1.3, 1> rotate <0, -20, 8> translate <0, -0.45, -0.6> pigment { rgb <0.25, 0.5, 0.9> } }
text { ttf "timrom.ttf" "g@&%", 1, 0 rotate <-90, 0, 0> translate <2.6, -0.5, -1.4> pigment { rgb <0.3, 0.8, 0.4> } }
