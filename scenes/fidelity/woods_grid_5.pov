// povml fidelity scene: woods_grid_5
// Rule: woods.inc's textures as POV-Ray renders them: P_WoodGrain19A, P_WoodGrain19B, T_Wood31, T_Wood32, T_Wood33
// Nine tiles, each a slanted box with one texture, lit by one light (a pigment is shown with
// the default finish).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "woods.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain19A } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain19B } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Wood31 } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Wood32 } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Wood33 } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
