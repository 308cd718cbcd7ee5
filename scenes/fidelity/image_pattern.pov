// povml fidelity scene: image_pattern
// Rule: image_pattern with a colour_map: the grey of the pixels
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0 pigment { image_pattern { png "../images/rgb8.png" } color_map { [0 rgb <0,0,0.3>] [0.5 rgb <1,0.5,0>] [1 rgb 1] } } finish { ambient 1 diffuse 0 } }
