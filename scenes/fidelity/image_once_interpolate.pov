// povml fidelity scene: image_once_interpolate
// Rule: once with bilinear interpolation: edge pixels are not wrapped
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0 pigment { image_map { png "../images/rgb8.png" once interpolate 2 } scale 0.6 translate <0.15,0.2,0> } finish { ambient 1 diffuse 0 } }
plane { z, 1 pigment { checker rgb <0.9,0.2,0.1>, rgb <0.1,0.3,0.8> scale 0.25 } finish { ambient 1 diffuse 0 } }
