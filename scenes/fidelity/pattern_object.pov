// povml fidelity scene: pattern_object
// Rule: object pattern (pattern.cpp object_pattern): 1 inside the object, 0 outside, the two
// colours listed inside its block; a CSG (a difference, rotated inside the block) and a
// transformed sphere (an ellipsoid). The object moves with the transforms written inside the
// block; the pattern's own transform (after the block) moves the point, not the object.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at <0, 0.5, 0> angle 60 }
#declare C = union { difference { box { <-1.5, -1, -1.5>, <1.5, 1, 1.5> } cylinder { <0, -2, 0>, <0, 2, 0>, 1 } rotate <0, 30, 0> } torus { 0.5, 0.1 } }
plane { y, 0
  pigment { object { C scale <1.2, 1, 0.8> rgb <0.1, 0, 0.4>, color rgb <1, 0.8, 0> } translate <0.3, 0, 0> }
  finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1
  pigment { object { sphere { 0, 1 scale <0.3, 1, 0.6> translate <0.3, 1.4, -0.5> } rgb <0, 0.7, 0.2> rgb <1, 0.1, 0.1> } }
  finish { ambient 1 diffuse 0 } }
