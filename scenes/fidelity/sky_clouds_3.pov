// povml fidelity scene: sky_clouds_3
// Rule: skies.inc's declared sky_sphere S_Cloud3, used by name and turned, over a plane
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "skies.inc"
camera { location <0, 1, -4> look_at <0, 2, 0> angle 70 }
light_source { <-3, 10, -6> rgb 1 }
sky_sphere { S_Cloud3 rotate x*5 }
plane { y, 0 pigment { checker rgb 0.3, rgb 0.6 } }
