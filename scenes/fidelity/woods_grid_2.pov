// povml fidelity scene: woods_grid_2
// Rule: woods.inc's textures as POV-Ray renders them: P_WoodGrain5B, P_WoodGrain6A, P_WoodGrain6B, P_WoodGrain7A, P_WoodGrain7B, P_WoodGrain8A, P_WoodGrain8B, P_WoodGrain9A, P_WoodGrain9B
// Nine tiles, each a slanted box with one texture, lit by one light (a pigment is shown with
// the default finish).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "woods.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain5B } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain6A } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain6B } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain7A } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain7B } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain8A } rotate <10, 85, 0> translate <2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain8B } rotate <10, 102, 0> translate <-2.1, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain9A } rotate <10, 119, 0> translate <0.0, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> pigment { P_WoodGrain9B } rotate <10, 136, 0> translate <2.1, 0, -2.1> }
