// povml fidelity scene: image_gamma
// Rule: the gamma keyword overrides the file's gAMA chunk
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { png "../images/rgb8.png" gamma 1.8 } }
  finish { ambient 1 diffuse 0 }
}
