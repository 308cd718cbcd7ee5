// povml fidelity scene: normal_slope_map
// Rule: a slope_map turns the pattern value into a height through the Hermite cubic of the
//       entries' heights and slopes around it (normal.cpp, Do_Slope_Map), and that height is
//       what the four tetrahedron samples see: gradient x made into rounded ridges on the floor,
//       a triangle-waved gradient into flat-topped bands on the sphere, steep steps on the box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> }
        normal { gradient x 2 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.7 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { gradient <0, 1, 0.3> 1 triangle_wave slope_map { [0 <0, 0>] [0.3 <1, 0>] [0.7 <1, 0>] [1 <0, 0>] } scale 0.3 }
         finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { gradient y 1 slope_map { [0 <0, 3>] [0.2 <0.6, 0>] [1 <0.2, -0.5>] } scale 0.4 }
      finish { specular 0.6 roughness 0.02 } }
