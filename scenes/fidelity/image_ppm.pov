// povml fidelity scene: image_ppm
// Rule: a binary PPM image_map: linear (no gamma) by default
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { ppm "../images/img.ppm" } }
  finish { ambient 1 diffuse 0 }
}
