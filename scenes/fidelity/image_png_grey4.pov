// povml fidelity scene: image_png_grey4
// Rule: a 4-bit grey PNG: levels decoded through a palette of 16
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { png "../images/g4.png" } }
  finish { ambient 1 diffuse 0 }
}
plane { z, 1 pigment { checker rgb <0.9,0.2,0.1>, rgb <0.1,0.3,0.8> scale 0.25 } finish { ambient 1 diffuse 0 } }
