// povml fidelity scene: normal_bumps
// Rule: bumps adds the vector noise at the point, times the bump size, to the normal in the
//       normal's space (normal.cpp, bumps; texture.cpp, DNoise). Fine bumps on the floor, coarse
//       ones on the sphere, stretched ones with a negative size on the box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { bumps 0.6 scale 0.1 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> } normal { bumps 1 scale 0.3 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { bumps -0.8 scale <0.6, 0.05, 0.2> } finish { specular 0.6 roughness 0.02 } }
