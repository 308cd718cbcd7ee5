// povml fidelity scene: normal_facets
// Rule: facets replaces the normal by the random point of the unit-cube grid nearest to the
//       normal scaled by 1/size (PickInCube over the 81 cubes around it, under the metric), or
//       with coords, adds the vector noise at the nearest point to the scaled hit point, less its
//       component along the normal (normal.cpp, facets). Size 0.1 on the sphere (the default),
//       coords 1 size 0.3 with metric 1 on the floor, size 0.2 metric 3 on the box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { facets coords 1 size 0.3 metric 1 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> } normal { facets } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { facets size 0.2 metric 3 } finish { specular 0.6 roughness 0.02 } }
