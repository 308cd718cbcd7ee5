// povml fidelity scene: normal_ripples
// Rule: ripples adds, for each of the 10 wave sources (the vector noise at <i,0,0> made unit),
//       the vector from the source to the point scaled by cycloidal(distance·frequency + phase)
//       times the bump size over (distance·10) (normal.cpp, ripples; texture.cpp,
//       Initialize_Waves). The default frequency on the floor, frequency 3 on the sphere,
//       a phase on the box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { ripples 0.8 scale 0.4 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> } normal { ripples 1.5 frequency 3 scale 0.5 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { ripples 1 phase 0.3 frequency 2 translate <1, 0, 0> scale 0.3 } finish { specular 0.6 roughness 0.02 } }
