// povml fidelity scene: image_pattern_index
// Rule: image_pattern use_index on a palette image: POV-Ray still takes the grey
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0 pigment { image_pattern { gif "../images/img.gif" use_index interpolate 2 } color_map { [0 rgb <0,0,0.3>] [1 rgb <1,1,0>] } } finish { ambient 1 diffuse 0 } }
