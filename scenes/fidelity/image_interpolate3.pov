// povml fidelity scene: image_interpolate3
// Rule: bicubic interpolation, magnified
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0 pigment { image_map { png "../images/rgb16.png" interpolate 3 } scale 4 translate <-1.2,-1.4,0> } finish { ambient 1 diffuse 0 } }
