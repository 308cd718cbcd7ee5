// povml fidelity scene: hf_mid
// Rule: a 120x90 16-bit field seen low from a corner: many blocks, long walks, smooth and flat halves
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <-0.1, 0.6, -0.2> look_at <0.7, 0.2, 0.8> angle 60 }
light_source { <-3, 5, -6> rgb 1 }
height_field { png "../images/hf_mid16.png" scale <1, 0.4, 1> pigment { rgb <0.8, 0.7, 0.5> } }
height_field { png "../images/hf_mid16.png" smooth scale <1, 0.4, 1> translate x pigment { rgb <0.6, 0.7, 0.9> } }
