// povml fidelity scene: blob_glass
// Rule: a glass blob is a closed solid: rays refract in and out through the field's gradient
//       normal, the interior list follows its Inside (field > threshold − 1e-6), and a blob
//       on its own reports the crossings of the first interval that has one (shape/blob.cpp).
// A glass blob of three spheres and a cylinder in front of coloured boxes.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, -5.5> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.25, 0.35, 0.55> }
light_source { <-3, 6, -5>, rgb 1 }
blob { threshold 0.5
  sphere { <-0.7, 1, 0>, 0.9, 1 }
  sphere { <0.7, 1, 0>, 0.9, 1 }
  sphere { <0, 1.6, -0.2>, 0.7, 1 }
  cylinder { <-1, 0.3, -0.5>, <1, 0.4, -0.6>, 0.35, 1 }
  pigment { rgbf <0.95, 0.98, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.8 reflection 0.05 }
  interior { ior 1.5 fade_distance 2 fade_power 1 } }
box { <-2, 0, 1.5>, <-1, 2, 2> pigment { rgb <0.9, 0.2, 0.2> } }
box { <-0.5, 0, 1.5>, <0.5, 2, 2> pigment { rgb <0.2, 0.9, 0.2> } }
box { <1, 0, 1.5>, <2, 2, 2> pigment { rgb <0.2, 0.2, 0.9> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
