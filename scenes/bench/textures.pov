// povml benchmark scene: render at +W640 +H480 +A0.3.
// Textures made of textures: layered stone textures from stones.inc, a texture_map of a
// reflective and a bumpy texture, an image_map from POV-Ray's include directory, over a plane with
// a two-layer texture; two lights.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
#include "colors.inc"
#include "stones.inc"
camera { location <0, 2.6, -7> look_at <0, 0.9, 0> right x*image_width/image_height angle 55 }
background { rgb <0.35, 0.5, 0.8> }
light_source { <-5, 8, -6>, rgb 1 }
light_source { < 6, 6, -3>, rgb 0.4 }
plane { y, 0
  texture { pigment { checker rgb <0.8, 0.78, 0.7>, rgb <0.3, 0.32, 0.35> } finish { reflection 0.15 } }
  texture { pigment { granite color_map { [0.4 rgbt 1] [1 rgbt <0.2, 0.15, 0.1, 0.5>] } scale 0.6 } normal { bumps 0.2 scale 0.05 } } }
sphere { <-2.6, 1, 0.6>, 1 texture { T_Stone24 scale 0.5 } }
sphere { <0, 1, 1.2>, 1
  texture { wood turbulence 0.2 scale 0.4 rotate <30, 20, 0>
    texture_map { [0.3 pigment { rgb <0.9, 0.75, 0.3> } finish { reflection 0.4 phong 0.8 }]
                  [0.7 pigment { rgb <0.4, 0.2, 0.1> } normal { dents 0.8 scale 0.1 }] } } }
sphere { <2.6, 1, 0.6>, 1 pigment { image_map { png "povmap.png" map_type 1 interpolate 2 } } finish { phong 0.5 } }
box { <-1.2, 0, -2.2>, <1.2, 0.5, -1.2> texture { T_Stone5 scale 0.4 } texture { pigment { rgbt <1, 1, 1, 0.7> } finish { reflection 0.2 } } }
