// povml fidelity scene: image_bump_interpolate
// Rule: bump_map with bilinear interpolation, magnified
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
light_source { <-3, 5, -6> rgb 1 }
plane { z, 0 pigment { rgb 0.8 } normal { bump_map { png "../images/rgb16.png" interpolate 2 bump_size 2 } scale 3 translate <-1,-1,0> } }
