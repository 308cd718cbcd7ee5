// povml fidelity scene: tex_layers2
// Rule: a layered texture (the last written on top): each layer is lit on its own, and the layer
//       below is seen through the top layer's filter and transmit (trace.cpp,
//       ComputeLightedTexture). Two layers: a solid base and a transmitting checker on top.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 texture { pigment { rgb <0.8, 0.75, 0.7> } }
        texture { pigment { checker rgbt <0.1, 0.2, 0.6, 0.3>, rgbt <1, 1, 1, 1> scale 0.5 } finish { phong 0.5 } } }
sphere { <-1.2, 0.9, 0.5>, 0.9
  texture { pigment { rgb <0.9, 0.3, 0.2> } finish { diffuse 0.8 } }
  texture { pigment { gradient y color_map { [0 rgbt <0, 0, 1, 0.2>] [0.5 rgbt 1] [1 rgbf <0, 1, 0, 0.6>] } scale 0.4 } finish { specular 0.5 } } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { pigment { rgb <0.3, 0.6, 0.9> } finish { ambient 0.3 } }
      texture { pigment { bozo color_map { [0.4 rgbt <1, 1, 0, 0>] [0.6 rgbt <1, 1, 1, 1>] } scale 0.3 } } }
