// povml fidelity scene: image_tga
// Rule: a true-colour Targa image_map, decoded as sRGB
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { tga "../images/img.tga" } }
  finish { ambient 1 diffuse 0 }
}
