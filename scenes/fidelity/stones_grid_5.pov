// povml fidelity scene: stones_grid_5
// Rule: stones.inc's textures as POV-Ray renders them: T_Grnt16, T_Grnt16a, T_Grnt17, T_Grnt17a, T_Grnt18, T_Grnt18a, T_Grnt22a, T_Grnt23, T_Grnt23a
// Nine tiles, each a slanted box with one texture, lit by one light (a pigment is shown with
// the default finish).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "stones.inc"
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt16 } rotate <10, 0, 0> translate <-2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt16a } rotate <10, 17, 0> translate <0.0, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt17 } rotate <10, 34, 0> translate <2.1, 0, 2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt17a } rotate <10, 51, 0> translate <-2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt18 } rotate <10, 68, 0> translate <0.0, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt18a } rotate <10, 85, 0> translate <2.1, 0, 0.0> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt22a } rotate <10, 102, 0> translate <-2.1, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt23 } rotate <10, 119, 0> translate <0.0, 0, -2.1> }
box { <-1, -0.1, -1>, <1, 0.1, 1> texture { T_Grnt23a } rotate <10, 136, 0> translate <2.1, 0, -2.1> }
