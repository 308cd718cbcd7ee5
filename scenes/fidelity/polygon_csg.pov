// povml fidelity scene: polygon_csg
// Rule: a polygon is not solid: its Inside is always false and inverse does nothing
//       (Polygon::Inside, Polygon::Invert; docs/povray-rules.md §15.7, §16.2, §16.3). So in an
//       intersection it keeps its own hits inside the other members and hides every other
//       member's hits; in a difference (the polygon not inverted) the same; in a merge it hides
//       nothing and keeps its hits outside the others; clipped_by keeps the part inside the clip.
// Left to right: intersection { polygon sphere } (the disc of the polygon inside the sphere),
// difference { sphere polygon } (the same), merge { sphere polygon } (the sphere and the
// polygon's part outside it), difference { polygon sphere } (a polygon with the sphere's disc
// cut away: the sphere inverted, its own hits hidden), a polygon clipped_by a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> right x*image_width/image_height angle 55 }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 8, -6>, rgb 1 }
light_source { <5, 4, -5>, rgb 0.3 }
#declare Square = polygon { 5, <-0.9, -0.9>, <0.9, -0.9>, <0.9, 0.9>, <-0.9, 0.9>, <-0.9, -0.9>
  pigment { rgb <0.95, 0.75, 0.2> } rotate <-20, 15, 0> }
intersection { object { Square } sphere { 0, 0.7 pigment { rgb <0.3, 0.6, 0.9> } } translate <-3.2, 1, 0.5> }
difference { sphere { 0, 0.7 pigment { rgb <0.3, 0.6, 0.9> } } object { Square } translate <-1.6, 1, 0.5> }
merge { sphere { 0, 0.6 pigment { rgb <0.3, 0.6, 0.9> } } object { Square } translate <0, 1, 0.5> }
difference { object { Square } sphere { 0, 0.6 pigment { rgb <0.3, 0.6, 0.9> } } translate <1.6, 1, 0.5> }
object { Square clipped_by { box { <-0.5, -2, -2>, <2, 0.4, 2> } } translate <3.2, 1, 0.5> }
union { object { Square } box { <-0.3, -0.3, -0.3>, <0.3, 0.3, 0.3> pigment { rgb <0.8, 0.3, 0.3> } }
  split_union off translate <0, 1, -1.8> scale 0.6 }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
