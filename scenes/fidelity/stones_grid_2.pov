// povml fidelity scene: stones_grid_2
// Rule: stones.inc's textures as POV-Ray renders them: T_Grnt2a, T_Grnt3, T_Grnt3a, T_Grnt4, T_Grnt4a, T_Grnt5, T_Grnt5a, T_Grnt6, T_Grnt6a
// Nine tiles, each a slanted box with one texture, lit by one light (a pigment is shown with
// the default finish).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "stones.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt2a } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt3 } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt3a } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt4 } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt4a } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt5 } rotate <10, 85, 0> translate <2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt5a } rotate <10, 102, 0> translate <-2.1, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt6 } rotate <10, 119, 0> translate <0.0, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt6a } rotate <10, 136, 0> translate <2.1, 0, -2.1> }
