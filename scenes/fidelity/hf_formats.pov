// povml fidelity scene: hf_formats
// Rule: heights from other files: PGM, TGA grey, a GIF palette (index·256), an 8-bit PPM (red·256 + green), hierarchy off
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1, 2.8, -2.2> look_at <1, 0, 0.6> angle 55 }
light_source { <-3, 5, -6> rgb 1 }
height_field { pgm "../images/hf_small.pgm" scale <0.9, 0.5, 0.9> pigment { rgb <0.9, 0.5, 0.5> } }
height_field { "../images/hf_small.tga" hierarchy off scale <0.9, 0.5, 0.9> translate x*1.1 pigment { rgb <0.5, 0.9, 0.5> } }
height_field { gif "../images/hf_pal.gif" scale <0.9, 0.5, 0.9> translate z*1.1 pigment { rgb <0.5, 0.5, 0.9> } }
height_field { ppm "../images/hf_rg.ppm" smooth scale <0.9, 0.5, 0.9> translate <1.1, 0, 1.1> pigment { rgb <0.9, 0.9, 0.5> } }
