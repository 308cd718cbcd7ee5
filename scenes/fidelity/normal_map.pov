// povml fidelity scene: normal_map
// Rule: with a normal_map, the pattern's value (wrapped and waved) picks the entries around it,
//       each entry's normal bends the normal at the point the outer pattern saw, and the two
//       results are blended by the value and made unit (normal.cpp, Perturb_Normal). A gradient
//       blends two gradients on the floor; the block form of checker picks one of two normals
//       per cell on the box; the hexagon block form inside a normal_map on the sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> }
        normal { gradient x normal_map { [0 gradient z 1 scale 0.3] [1 quilted 0.8 scale 0.25] } scale 3 }
        finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { gradient y normal_map {
                    [0.3 gradient x 1 triangle_wave scale 0.15]
                    [0.7 hexagon normal { quilted 1 scale 0.2 }, normal { gradient z 1 scale 0.1 }, normal { gradient x 0.5 scale 0.1 } scale 0.5] }
                  translate -y*0.2 scale 2 }
         finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { checker normal { gradient x 1 scale 0.1 }, normal { quilted 1 scale 0.15 } scale 0.5 }
      finish { specular 0.6 roughness 0.02 } }
