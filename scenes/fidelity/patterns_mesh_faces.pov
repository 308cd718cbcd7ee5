// povml fidelity scene: patterns_mesh_faces
// Rule: a mesh's per-face textures (declared, with patterns) and its own texture move with the
//       mesh's transforms (docs/povray-rules.md §14.7, §2.6); a texture block's transforms move its pigment;
//       a declared colour map of textures.inc is used by a gradient (§17.3).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "textures.inc"
camera { location <0, 3, -5> look_at <0, 0.5, 0> right x*image_width/image_height }
light_source { <3, 8, -4> color rgb 1 }
#declare TA = texture { pigment { checker Red, White scale 0.25 } finish { phong 0.5 } }
#declare TB = texture { pigment { gradient y color_map { Blue_Sky_Map } scale 0.5 } }
mesh {
  triangle { <-1,0,0>, <1,0,0>, <0,1.5,0> texture { TA } }
  triangle { <-1,0,0>, <0,0,-1>, <0,1.5,0> texture { TB } }
  triangle { <1,0,0>, <0,0,-1>, <0,1.5,0> }
  texture { pigment { hexagon scale 0.1 } }
  rotate <0, 25, 0> translate <0.2, 0.1, 0> scale 1.3
}
plane { y, 0 texture { pigment { brick rgb 0.9, rgb <0.6,0.3,0.2> scale 0.1 } rotate y*30 translate x*0.3 } }
