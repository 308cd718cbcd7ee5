// povml fidelity scene: normal_quilted
// Rule: quilted has a normal of its own: the offset of the point from the centre of its unit cell
//       (FLOOR, one below floor at negative integers), scaled by the cubic with control values
//       control0 and control1, times the bump size, is added to the normal (normal.cpp, quilted;
//       pattern.cpp, quilt_cubic). Default controls on the floor, control0 0 control1 1 on the
//       sphere, control0 1 control1 0 on the box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { quilted 0.8 scale 0.6 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { quilted 1 control0 0 control1 1 scale 0.3 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { quilted 0.6 control0 1 control1 0 scale 0.35 } finish { specular 0.6 roughness 0.02 } }
