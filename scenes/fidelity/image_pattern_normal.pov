// povml fidelity scene: image_pattern_normal
// Rule: image_pattern as a normal's pattern (its slope)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.6> look_at <0.5, 0.5, 0> angle 50 }
light_source { <-3, 5, -6> rgb 1 }
plane { z, 0 pigment { rgb 0.8 } normal { image_pattern { png "../images/rgb8.png" interpolate 2 } 2 } }
