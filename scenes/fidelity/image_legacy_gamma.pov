// povml fidelity scene: image_legacy_gamma
// Rule: a pre-3.7 scene with assumed_gamma 2.2: files without gamma information take the working gamma
#version 3.6;
global_settings { assumed_gamma 2.2 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { ppm "../images/img.ppm" } }
  finish { ambient 1 diffuse 0 }
}
