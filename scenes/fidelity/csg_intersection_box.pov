// Rule: an intersection's box is the overlap of its members' POV-Ray boxes as POV-Ray keeps them
// (CSG::Compute_BBox), not of tighter ones: shapes.inc's Bevelled_Text is an intersection of sheared
// texts, and Center_Object and Align_Object move it by its min_extent and max_extent.
#version 3.7;
#include "shapes.inc"
global_settings { assumed_gamma 1.0 max_trace_level 10 }
#default {finish {ambient 0}}
camera { location <-2.0, 3.5,-8.5> up y right x*image_width/image_height angle 25 look_at <-1.5, 0.5, 0.0> }
light_source {<-150, 200,-100>, color 0.8 * <1.0, 1.0, 0.6>}
object {
   Align_Object( Center_Object(Bevelled_Text("crystal.ttf", "POV", 1, 45, 0.025, 0.25, 0, no), x) -y, < 0, 0, 0>)
   texture { pigment {color <0.5,0.3,0.1>} finish { diffuse 0.8 brilliance 2   } }
   scale 2 translate <-1.5, 0.0,-0.5>
}
