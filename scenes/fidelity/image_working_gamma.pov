// povml fidelity scene: image_working_gamma
// Rule: working gamma 2.2: an sRGB file transcoded to it
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { png "../images/nogamma.png" } }
  finish { ambient 1 diffuse 0 }
}
