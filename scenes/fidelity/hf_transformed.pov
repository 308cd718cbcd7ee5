// povml fidelity scene: hf_transformed
// Rule: modifiers compose into the scaling transform: non-uniform scale, rotate, translate; smooth normals through the inverse transpose
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-3, 5, -6> rgb 1 }
height_field { png "../images/hf_grey8.png"
  translate <-0.5, 0, -0.5> scale <3, 0.6, 2> rotate <-15, 30, 10> translate <0, 0, 0.5>
  pigment { rgb <0.5, 0.8, 0.5> } }
height_field { pgm "../images/hf_small.pgm" smooth
  scale <1.5, 0.4, 1> rotate y*-20 translate <-2.2, -0.6, -1.5>
  pigment { rgb <0.9, 0.6, 0.4> } finish { specular 0.5 } }
plane { y, -1 pigment { checker rgb 0.3 rgb 0.6 } }
