// povml fidelity scene: image_interpolate_palette
// Rule: bilinear interpolation of a palette image
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0 pigment { image_map { gif "../images/img.gif" interpolate 2 } scale 3 translate <-0.8,-0.9,0> } finish { ambient 1 diffuse 0 } }
