// Rule: a declared pigment, finish or normal starts from the #default texture's (POV-Ray copies
// Default_Texture's pigment, normal and finish before it reads the block): here ambient 0, an
// orange pigment and a bumpy normal reach the declared F, P, N and Q.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#default { pigment { rgb <0.9, 0.4, 0.2> } normal { bumps 0.6 scale 0.2 } finish { ambient 0 } }
camera { location <0, 0, -5> look_at 0 }
light_source { <-150, 200, -100>, color 1 }
#declare F = finish { diffuse 0.7 }
#declare P = pigment { }
#declare N = normal { }
#declare Q = pigment { checker rgb 1, rgb <0.2, 0.5, 0.9> }
sphere { <-1.2, 0, 0>, 0.9 pigment { P } normal { N } finish { F } }
sphere { <1.2, 0, 0>, 0.9 texture { pigment { Q scale 0.3 } normal { N } finish { F } } }
plane { z, 1 pigment { rgb 0.8 } finish { F } }
