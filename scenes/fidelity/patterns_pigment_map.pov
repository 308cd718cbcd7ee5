// povml fidelity scene: patterns_pigment_map
// Rule: checker pigment {…}, pigment {…} and pigment_map { [v PIGMENT] … } look up whole
//       pigments by the map rules and evaluate them at the point the outer pattern saw, each
//       through its own transform, blending their colours (docs/povray-rules.md §17.2, §17.3, §17.4).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> right x*image_width/image_height }
light_source { <4, 9, -5> color rgb 1 }
plane { y, 0 pigment { checker pigment { gradient x color_map { [0 rgb <1,0,0>] [1 rgb <1,1,0>] } scale 0.5 }, pigment { hexagon scale 0.2 } scale 2 } }
sphere { <0,1,0>, 1 pigment { gradient y pigment_map { [0.2 checker rgb 1, rgb 0 scale 0.2] [0.5 rgb <0,0.5,1>] [0.8 brick rgb 0.2, rgb <0.8,0.3,0.1> brick_size 0.3 mortar 0.05] } translate -0.5*y scale 2 } }
box { <1.6,0,-1.5>, <2.6,1.5,-0.5> pigment { gradient x pigment_map { [0 checker pigment { rgbt <1,1,1,0.7> }, pigment { rgb <0.2,0.2,0.9> } scale 0.25] [1 rgbf <0.9,0.4,0.1,0.6>] } } }
