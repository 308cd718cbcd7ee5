// Reflection and refraction off transformed shapes: the hit point, the normal and the inside test
// of ellipsoids, a transformed plane and a moved mesh all feed secondary rays (§14.5, §14.6).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0.3, 2.2, -6> look_at <0, 0.9, 0> right x*image_width/image_height angle 55 }
background { rgb <0.25, 0.3, 0.45> }
light_source { <-3, 6, -4>, rgb 1 }
light_source { <5, 2, -3>, rgb <0.5, 0.45, 0.4> }
sphere { 0, 1
  pigment { rgb <0.9, 0.9, 0.95> } finish { reflection 0.8 phong 0.9 phong_size 60 }
  scale <1.1, 0.6, 0.8>
  rotate <0, 30, 15>
  translate <-1.3, 0.9, 0.4>
}
sphere { 0, 1
  pigment { rgbf <0.95, 0.97, 1, 0.9> } finish { phong 0.8 } interior { ior 1.5 }
  scale <0.7, 1.1, 0.7>
  matrix <1, 0, 0.2, 0.3, 1, 0, 0, 0, 1, 0, 0, 0>
  translate <1.1, 1.1, -0.3>
}
mesh {
  triangle { <1,0,0>, <0,1,0>, <0,0,1> }
  triangle { <0,0,1>, <0,1,0>, <-1,0,0> }
  triangle { <-1,0,0>, <0,1,0>, <0,0,-1> }
  triangle { <0,0,-1>, <0,1,0>, <1,0,0> }
  triangle { <1,0,0>, <0,-1,0>, <0,0,1> }
  triangle { <0,0,1>, <0,-1,0>, <-1,0,0> }
  triangle { <-1,0,0>, <0,-1,0>, <0,0,-1> }
  triangle { <0,0,-1>, <0,-1,0>, <1,0,0> }
  inside_vector <0.1, 1, 0.2>
  pigment { rgbf <0.6, 1, 0.7, 0.8> } finish { reflection 0.2 } interior { ior 1.3 }
  scale <0.5, 0.8, 0.5>
  rotate <10, 20, 30>
  translate <0, 0.8, 1.8>
}
plane { y, 0
  pigment { rgb <0.7, 0.7, 0.65> } finish { reflection 0.3 }
  matrix <1, 0, 0, 0.05, 1, 0.02, 0, 0, 1, 0, 0, 0>
}
plane { z, 6
  pigment { rgb <0.8, 0.5, 0.4> }
  rotate <0, -20, 0>
  scale <1, 1, 1.5>
}
