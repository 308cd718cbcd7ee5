// povml fidelity scene: hf_water
// Rule: water_level: heights below it are raised in Inside and in the blocks; the box starts at it
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 1.2, -1.2> look_at <0.5, 0.2, 0.5> angle 50 }
light_source { <-3, 5, -6> rgb 1 }
height_field { png "../images/hf_grey8.png" water_level 0.45 pigment { rgb <0.8, 0.7, 0.5> } }
box { <0.1, 0, 0.1>, <0.9, 0.5, 0.9> pigment { rgbf <0.6, 0.7, 1, 0.6> } }
