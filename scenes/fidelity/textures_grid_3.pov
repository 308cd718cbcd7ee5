// povml fidelity scene: textures_grid_3
// Rule: textures.inc's pattern textures and pigments as POV-Ray renders them: DMFWood5, DMFDarkOak, DMFLightOak, Cork, Candy_Cane, Peel, Lightning1, Lightning2, Starfield
// Nine tiles, each a slanted box with one of them (a pigment standing for its texture, as
// POV-Ray allows), lit by one light.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "textures.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { DMFWood5 } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { DMFDarkOak } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { DMFLightOak } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Cork } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Candy_Cane } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Peel } rotate <10, 85, 0> translate <2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Lightning1 } rotate <10, 102, 0> translate <-2.1, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Lightning2 } rotate <10, 119, 0> translate <0.0, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { Starfield } rotate <10, 136, 0> translate <2.1, 0, -2.1> }
