// povml fidelity scene: image_legacy
// Rule: a pre-3.7 scene without assumed_gamma: the file's raw values
#version 3.6;

camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { png "../images/rgb8.png" } }
  finish { ambient 1 diffuse 0 }
}
