// povml fidelity scene: image_by_extension
// Rule: the file type inferred from the name's extension
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { "../images/img.tga" } }
  finish { ambient 1 diffuse 0 }
}
