// povml fidelity scene: image_png_grey_alpha
// Rule: an 8-bit grey and alpha PNG read as premultiplied
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { png "../images/ga.png" premultiplied on } }
  finish { ambient 1 diffuse 0 }
}
plane { z, 1 pigment { checker rgb <0.9,0.2,0.1>, rgb <0.1,0.3,0.8> scale 0.25 } finish { ambient 1 diffuse 0 } }
