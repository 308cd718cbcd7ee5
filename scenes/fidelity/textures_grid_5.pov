// povml fidelity scene: textures_grid_5
// Rule: textures.inc's pattern textures and pigments as POV-Ray renders them: FBM_Clouds, Water, Brushed_Aluminum, Brass_Valley, Gold_Nugget
// Nine tiles, each a slanted box with one of them (a pigment standing for its texture, as
// POV-Ray allows), lit by one light.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "textures.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { FBM_Clouds } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Water } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Brushed_Aluminum } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Brass_Valley } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Gold_Nugget } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
