// povml fidelity scene: hf_plain
// Rule: a height field alone from an 8-bit grey PNG: flat triangles, the block walk, normals as intersect_pixel stores them
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 1.2, -1.2> look_at <0.5, 0.2, 0.5> angle 50 }
light_source { <-3, 5, -6> rgb 1 }
height_field { png "../images/hf_grey8.png" pigment { rgb <0.8, 0.7, 0.5> } }
