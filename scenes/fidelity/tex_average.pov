// povml fidelity scene: tex_average
// Rule: average weighs every texture of its map by its value (1 when left out) and divides by
//       the sum (ComputeAverageTextureColours).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 texture { average texture_map { [1 pigment { checker rgb 1, rgb 0 }] [2 pigment { rgb <0.2, 0.4, 0.9> } finish { reflection 0.2 }] } } }
sphere { <-1.1, 1, 0.5>, 1 texture { average texture_map { [pigment { rgb <1, 0, 0> } finish { phong 1 }] [pigment { rgb <0, 1, 0> } normal { bumps 1 scale 0.2 }] [pigment { rgbt <0, 0, 1, 0.8> }] } } }
