// povml fidelity scene: stones_grid_3
// Rule: stones.inc's textures as POV-Ray renders them: T_Grnt7, T_Grnt7a, T_Grnt8, T_Grnt8a, T_Grnt9, T_Grnt9a, T_Grnt10, T_Grnt10a, T_Grnt11
// Nine tiles, each a slanted box with one texture, lit by one light (a pigment is shown with
// the default finish).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "stones.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt7 } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt7a } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt8 } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt8a } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt9 } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt9a } rotate <10, 85, 0> translate <2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt10 } rotate <10, 102, 0> translate <-2.1, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt10a } rotate <10, 119, 0> translate <0.0, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt11 } rotate <10, 136, 0> translate <2.1, 0, -2.1> }
