// povml fidelity scene: woods_grid_4
// Rule: woods.inc's textures as POV-Ray renders them: P_WoodGrain14B, P_WoodGrain15A, P_WoodGrain15B, P_WoodGrain16A, P_WoodGrain16B, P_WoodGrain17A, P_WoodGrain17B, P_WoodGrain18A, P_WoodGrain18B
// Nine tiles, each a slanted box with one texture, lit by one light (a pigment is shown with
// the default finish).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "woods.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain14B } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain15A } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain15B } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain16A } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain16B } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain17A } rotate <10, 85, 0> translate <2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain17B } rotate <10, 102, 0> translate <-2.1, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain18A } rotate <10, 119, 0> translate <0.0, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain18B } rotate <10, 136, 0> translate <2.1, 0, -2.1> }
