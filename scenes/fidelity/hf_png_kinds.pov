// povml fidelity scene: hf_png_kinds
// Rule: heights from PNG kinds: 16-bit RGB (grey × 65535), a palette (index × 256), 8-bit RGB (red high byte, green low), in a kept union
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1, 2.8, -2.2> look_at <1, 0, 0.6> angle 55 }
light_source { <-1, 8, -3> rgb 1 }
union {
  height_field { png "../images/hf_rgb16.png" scale <0.9, 0.5, 0.9> pigment { rgb <0.9, 0.5, 0.5> } }
  height_field { png "../images/hf_pal.png" smooth scale <0.9, 8, 0.9> translate x*1.1 pigment { rgb <0.5, 0.9, 0.5> } }
  height_field { png "../images/hf_rgb8.png" scale <0.9, 0.5, 0.9> translate z*1.1 pigment { rgb <0.5, 0.5, 0.9> } }
  split_union off
}
