// height_field { function W, H { pigment { … } } }: the pigment's grey as the height
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -10> rgb 1 }

height_field { function 80, 80 { pigment { checker color rgb 1 color rgb 0.2 scale 0.25 } }
  translate <-0.5, 0, -0.5> scale <5, 0.5, 5> pigment { rgb <0.8, 0.6, 0.4> } }
