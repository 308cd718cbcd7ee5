// povml fidelity scene: image_repeat_offset
// Rule: repeat and offset
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0
  pigment { image_map { png "../images/rgb8.png" repeat <2, 3> offset <0.25, 0.1> } }
  finish { ambient 1 diffuse 0 }
}
