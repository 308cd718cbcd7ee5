// povml fidelity scene: quadric_ties
// Rule: a quadric bounded by its CSG ties with a coplanar face of another object, and POV-Ray
//       keeps the object whose single-precision box its bounding tree enters first
//       (docs/povray-rules.md §2.1, §15.8). The CSG's box comes from CSG::Compute_BBox, which bounds a
//       quadric member last, within the other members' box (Quadric::Compute_BBox with a clip
//       box); clipped_by does the same for a clipped quadric.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 3, -4> look_at <0, 0.3, 0> right x*image_width/image_height }
light_source { <-5, 9, -6>, rgb 1 }
#include "shapes.inc"
intersection { object { Cylinder_Y scale 0.8 } box { <-1, -1, -1>, <1, 0.5, 1> } pigment { rgb <0.2, 0.9, 0.2> } translate x*-1.1 }
box { <-1.5, 0.2, -0.3>, <-0.7, 0.5, 0.3> pigment { rgb <0.9, 0.2, 0.2> } }
object { Cylinder_Z scale 0.5 clipped_by { box { <-1, -1, -1>, <1, 1, 1> } } pigment { rgb <0.3, 0.3, 0.9> } translate <1.1, 0, 0> }
box { <0.6, -0.5, -1>, <1.6, 0.5, 1> pigment { rgb <0.9, 0.9, 0.2> } }
plane { y, -1 pigment { rgb 0.7 } }
