// povml fidelity scene: quadric_shapes_inc
// Rule: the quadrics of POV-Ray's shapes.inc (declared in shapes_old.inc: Cylinder_X/Y/Z,
//       QCone_X/Y/Z, Paraboloid_X/Y/Z, Hyperboloid, Hyperboloid_Y; Ellipsoid is a sphere there),
//       used through object { Id … } with scale and translate (which change the coefficients),
//       cut by boxes in intersections, by clipped_by, and alone (unbounded).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
camera { location <0, 5, -9> look_at <0, 0.6, 0> right x*image_width/image_height angle 50 }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-5, 9, -6>, rgb 1 }
light_source { <6, 5, -3>, rgb 0.4 }
#declare Cut = box { <-1, -1, -1>, <1, 1, 1> }
// back row: the three cylinders, each cut to a cube
intersection { object { Cylinder_X scale 0.4 } object { Cut scale 0.6 } pigment { rgb <0.9, 0.3, 0.2> } translate <-2.5, 0.6, 2> }
intersection { object { Cylinder_Y scale 0.4 } object { Cut scale 0.6 } pigment { rgb <0.3, 0.8, 0.3> } translate <-1, 0.6, 2> }
intersection { object { Cylinder_Z scale 0.4 } object { Cut scale 0.6 } pigment { rgb <0.3, 0.4, 0.9> } translate <0.5, 0.6, 2> }
object { Ellipsoid scale <0.7, 0.4, 0.5> pigment { rgb <0.9, 0.9, 0.3> } translate <2.2, 0.4, 2> }
// middle row: the three cones
intersection { object { QCone_X } object { Cut scale 0.6 } pigment { rgb <0.9, 0.5, 0.2> } translate <-2.5, 0.6, 0.3> }
intersection { object { QCone_Y } object { Cut scale 0.6 } pigment { rgb <0.5, 0.9, 0.5> } translate <-1, 0.6, 0.3> }
object { QCone_Z clipped_by { object { Cut scale 0.6 } } pigment { rgb <0.5, 0.6, 1> } translate <0.5, 0.6, 0.3> }
intersection { object { Hyperboloid_Y scale 0.3 } object { Cut scale 0.6 } pigment { rgb <0.8, 0.4, 0.8> } translate <2.2, 0.6, 0.3> }
// front row: the paraboloids and the other hyperboloid
intersection { object { Paraboloid_X scale 0.5 } object { Cut scale 0.6 } pigment { rgb <0.9, 0.7, 0.3> } translate <-2.5, 0.6, -1.5> }
intersection { object { Paraboloid_Y scale 0.5 } object { Cut scale <0.6, 0.6, 0.6> } pigment { rgb <0.4, 0.9, 0.9> } translate <-1, 0.6, -1.5> }
object { Paraboloid_Z scale 0.5 clipped_by { object { Cut scale 0.6 } } pigment { rgb <0.9, 0.4, 0.5> } translate <0.5, 0.6, -1.5> }
intersection { object { Hyperboloid scale 0.4 } object { Cut scale 0.6 } pigment { rgb <0.7, 0.7, 0.9> } translate <2.2, 0.6, -1.5> }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
