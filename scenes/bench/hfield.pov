// povml benchmark scene: render at +W320 +H240 -A (make the height map first:
// bash scenes/bench/gen_hfield.sh, which writes scenes/bench/generated/hfield_1024.png).
// A 1024×1024 16-bit height field (2 million triangles, 33×33 blocks), smooth, seen low across
// it, lit and shadowed, with a water plane: the block walk and the cell walk of long rays.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-1, 2.2, -2> look_at <5, 0.4, 5> angle 60 }
light_source { <-20, 15, -5> rgb 1 }
light_source { <10, 30, -20> rgb 0.3 shadowless }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.7, 0.8, 1>] [1 rgb <0.2, 0.3, 0.8>] } } }
height_field { png "generated/hfield_1024.png" smooth
  scale <10, 1.6, 10>
  pigment { gradient y color_map { [0 rgb <0.3, 0.5, 0.2>] [0.5 rgb <0.5, 0.45, 0.3>] [0.8 rgb <0.9, 0.9, 0.9>] } scale 1.6 }
  finish { diffuse 0.8 specular 0.1 } }
plane { y, 0.5 pigment { rgbf <0.3, 0.5, 0.7, 0.5> } finish { reflection 0.2 } }
