// height_field { function W, H { … } }: a 16-bit image made of a float function
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }

height_field { function 64, 48 { sin(x * 9) * cos(y * 7) * 0.4 + 0.5 } smooth
  translate <-0.5, 0, -0.5> scale <5, 1.5, 5> pigment { gradient y color_map { [0 rgb <0,0.3,0>] [1 rgb 1] } scale 1.5 } }
