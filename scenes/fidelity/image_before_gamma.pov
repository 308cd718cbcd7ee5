// povml fidelity scene: image_before_gamma
// Rule: an image read before assumed_gamma is not decoded (the file's raw values)
#version 3.7;
#declare P = pigment { image_map { png "../images/rgb8.png" } }
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
plane { z, 0 pigment { P } finish { ambient 1 diffuse 0 } }
