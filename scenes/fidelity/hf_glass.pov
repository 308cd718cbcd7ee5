// povml fidelity scene: hf_glass
// Rule: a glass height field: refraction through its normals, Inside for the interior, a solid box behind
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.2, -3> look_at <0, 0.2, 0> angle 45 }
light_source { <-3, 5, -6> rgb 1 }
intersection {
  height_field { png "../images/hf_grey16.png" smooth translate <-0.5, 0, -0.5> scale <2.4, 0.8, 2.4> }
  box { <-1, -0.2, -1>, <1, 2, 1> }
  pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { reflection 0.1 specular 0.6 } interior { ior 1.4 } }
plane { y, -0.2 pigment { checker rgb 0.2 rgb 0.9 scale 0.25 } }
box { <-2, -0.2, 1.2>, <2, 1.5, 1.4> pigment { gradient x color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } scale 0.5 } }
