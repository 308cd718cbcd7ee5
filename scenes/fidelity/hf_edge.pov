// povml fidelity scene: hf_edge
// Rule: edge-on: the camera at the field's level, rays grazing its cells and walking long rows (the stiff case)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <-0.2, 0.45, 0.5> look_at <1.2, 0.45, 0.5> angle 60 }
light_source { <-2, 6, 1> rgb 1 }
height_field { png "../images/hf_grey8.png" pigment { rgb <0.8, 0.7, 0.5> } }
height_field { tga "../images/hf_small.tga" scale <1, 0.1, 1> translate <0, 1.0, 0> pigment { rgb <0.5, 0.7, 0.9> } }
