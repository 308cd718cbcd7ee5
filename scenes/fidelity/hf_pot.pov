// A height field read from a POT file (Fractint's 16-bit continuous potential): a GIF twice as
// wide as the field, each height the left half's index times 256 plus the right half's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 1.4, -0.9> look_at <0.5, 0, 0.45> angle 50 }
light_source { <-2, 3, -1> rgb 1 }
light_source { <3, 2, -2> rgb 0.4 shadowless }
background { rgb <0.1, 0.1, 0.2> }
height_field { pot "mtmand.pot" water_level 0.05 pigment { gradient y color_map { [0 rgb <0.2, 0.3, 0.8>] [0.5 rgb <0.9, 0.8, 0.6>] [1 rgb 1] } } scale <0.5, 0.3, 1> }
height_field { pot "mtmand.pot" smooth pigment { rgb <0.8, 0.6, 0.4> } scale <0.5, 0.3, 1> translate <0.5, 0, 0> }
