// povml fidelity scene: superq_clipped
// Rule: clipped_by keeps a shape's hits inside the clip objects (POV-Ray tests Point_In_Clip in
//       each shape's insert_hit; povml clips the shape's hits outside it): a superellipsoid cut
//       open (seen inside through double_illuminate), an ovus and a sphere sweep cut by boxes
//       and planes.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
light_source { <-4, 7, -6>, rgb 1 }
superellipsoid { <0.3, 0.3> clipped_by { plane { z, 0.2 } } translate <-1.3, 1, 0> pigment { rgb x } double_illuminate }
ovus { 1, 0.6 clipped_by { box { <-2, 0.3, -2>, <2, 3, 0.2> } } translate <1.3, 0.2, 0> pigment { rgb y } }
sphere_sweep { linear_spline 2, <-1,0,0>, 0.3, <1,0,0>, 0.4 clipped_by { plane { -z, 0 } } translate <0, 0.4, -1.5> pigment { rgb z } }
plane { y, 0 pigment { rgb 0.8 } }
