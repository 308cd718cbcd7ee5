// povml fidelity scene: image_pattern_alpha
// Rule: image_pattern use_alpha: the transmit of an RGBA image as the value
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0 pigment { image_pattern { png "../images/alpha.png" use_alpha } color_map { [0 rgb <0,0,0.3>] [1 rgb <1,1,0>] } } finish { ambient 1 diffuse 0 } }
