// povml fidelity scene: hf_smooth
// Rule: smooth: the per-vertex normals stored as shorts, blended bilinearly (16-bit PNG heights)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 1.0, -1.0> look_at <0.5, 0.25, 0.5> angle 45 }
light_source { <-3, 5, -6> rgb 1 }
light_source { <3, 6, -4> rgb <0.3, 0.3, 0.5> }
height_field { png "../images/hf_grey16.png" smooth pigment { rgb 0.8 } finish { phong 0.8 phong_size 30 } }
