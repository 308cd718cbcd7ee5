// povml fidelity scene: normal_average
// Rule: average bends the normal by each entry of its normal_map and takes the mean of the
//       results weighted by the entries' values (summed in single precision), then the average's
//       own transform takes it back (normal.cpp, Do_Average_Normals). Equal weights of two
//       crossed gradients on the floor, weights 1 and 3 on the sphere, an average of an average
//       on the box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> }
        normal { average normal_map { [1 gradient x 0.8 triangle_wave scale 0.4] [1 gradient z 0.8 triangle_wave scale 0.3] } }
        finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { average normal_map { [1 quilted 1 scale 0.2] [3 gradient y 1 sine_wave scale 0.15] } rotate z*20 }
         finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { average normal_map {
                 [0.3 average normal_map { [1 brick 1 scale 0.2] [2 quilted 0.5 scale 0.3] }]
                 [0.7 gradient <1, 1, 1> 1 triangle_wave scale 0.25] } }
      finish { specular 0.6 roughness 0.02 } }
