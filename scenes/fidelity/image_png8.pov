// povml fidelity scene: image_png8
// Rule: an 8-bit RGB PNG (gAMA chunk) as a planar image_map, repeated, shown unlit
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { png "../images/rgb8.png" } }
  finish { ambient 1 diffuse 0 }
}
