// charset utf8: accented letters by the fonts' Unicode maps (Microsoft platform, format 4)
#version 3.7;
global_settings { assumed_gamma 1 charset utf8 }
camera { location <1.5, 0.5, -4> look_at <1.5, 0.4, 0> angle 45 }
light_source { <-5, 10, -10>, rgb 1 }
plane { z, 0.6 pigment { rgb <0.8, 0.8, 0.7> } }
text { ttf "timrom.ttf" "Àéü ñ Ça", 0.2, 0 pigment { rgb <0.9, 0.3, 0.2> } }
text { ttf "cyrvetic.ttf" "Öß ¿é?", 0.2, 0 translate -y pigment { rgb <0.2, 0.3, 0.9> } }
