// povml fidelity scene: textures_grid_1
// Rule: textures.inc's pattern textures and pigments as POV-Ray renders them: Jade, Red_Marble, White_Marble, Blood_Marble, Blue_Agate, Sapphire_Agate, Brown_Agate, Pink_Granite, Cherry_Wood
// Nine tiles, each a slanted box with one of them (a pigment standing for its texture, as
// POV-Ray allows), lit by one light.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "textures.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Jade } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Red_Marble } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { White_Marble } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Blood_Marble } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Blue_Agate } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Sapphire_Agate } rotate <10, 85, 0> translate <2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Brown_Agate } rotate <10, 102, 0> translate <-2.1, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Pink_Granite } rotate <10, 119, 0> translate <0.0, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Cherry_Wood } rotate <10, 136, 0> translate <2.1, 0, -2.1> }
