// povml fidelity scene: stones_grid_4
// Rule: stones.inc's textures as POV-Ray renders them: T_Grnt11a, T_Grnt12, T_Grnt12a, T_Grnt13, T_Grnt13a, T_Grnt14, T_Grnt14a, T_Grnt15, T_Grnt15a
// Nine tiles, each a slanted box with one texture, lit by one light (a pigment is shown with
// the default finish).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "stones.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt11a } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt12 } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt12a } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt13 } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt13a } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt14 } rotate <10, 85, 0> translate <2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt14a } rotate <10, 102, 0> translate <-2.1, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt15 } rotate <10, 119, 0> translate <0.0, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt15a } rotate <10, 136, 0> translate <2.1, 0, -2.1> }
