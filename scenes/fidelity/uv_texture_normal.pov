// povml fidelity scene: uv_texture_normal
// Rule: texture { uv_mapping … } evaluates the whole texture, its normal too, at the hit's
//       (u, v, 0) (UV_MAP_PATTERN in ComputeOneTextureColour); transforms applied to the object
//       afterwards only bend the normals; interior_texture { uv_mapping … } likewise.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-1.1, 1, 0.5>, 1 texture { uv_mapping pigment { checker rgb <1, 0.3, 0.2>, rgb 0.9 scale <0.1, 0.2, 1> } normal { gradient x 1 scale 0.05 } finish { phong 0.6 } } scale <1, 1, 1.2> }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { uv_mapping pigment { gradient x color_map { [0 rgb <0.2, 0.2, 0.9>] [1 rgb 1] } } normal { bumps 0.6 scale 0.05 } } rotate 15*y }
difference { sphere { <0.6, 1.9, 1.5>, 0.6 } box { <0.6, 1.9, 0>, <2, 3, 2> }
  texture { uv_mapping pigment { checker rgb 1, rgb 0 scale 0.1 } }
  interior_texture { uv_mapping pigment { rgb <1, 1, 0> } normal { ripples 0.5 scale 0.1 } } }
