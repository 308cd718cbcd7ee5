// povml fidelity scene: tex_material_map
// Rule: material_map { IMAGE texture {…} … }: the pixel at the warped point picks a texture, by
//       its palette index or, in an image without one, its red times 255 (more than the textures:
//       the remainder); off a once image the first texture (imageutil.cpp's material_map).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 texture { material_map { png "../images/pal.png" interpolate 2
    texture { pigment { rgb <1, 0.2, 0.2> } } texture { pigment { rgb <0.2, 1, 0.2> } finish { phong 1 } }
    texture { pigment { rgb <0.2, 0.2, 1> } normal { bumps 0.5 scale 0.05 } } texture { pigment { rgb 1 } finish { reflection 0.3 } } }
  rotate x*90 scale 2 } }
sphere { <-1.1, 1, 0.5>, 1 texture { material_map { png "../images/rgb8.png" map_type 1
    texture { pigment { rgb <1, 1, 0> } } texture { pigment { rgb <0, 1, 1> } } texture { pigment { checker rgb 0, rgb 1 scale 0.1 } } } } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { material_map { png "../images/grey.png" once
    texture { pigment { rgbt <1, 0.5, 0, 0.5> } } texture { pigment { rgb <0.5, 0, 1> } } } translate <0.5, 0.2, 0> } }
