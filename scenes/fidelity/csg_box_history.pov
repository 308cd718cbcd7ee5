// A union's bounding box is made when the union is built and then mapped by each later transform
// (POV-Ray's CSG::Compute_BBox at the end of the union, Recompute_BBox per transform), not remade
// from its members: rotated unions have loose boxes. min_extent/max_extent report those boxes, so
// the markers and the centred text below sit where POV-Ray puts them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -9> look_at <0, 0.5, 0> }
light_source { <-5, 10, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -2 pigment { checker rgb 0.8 rgb 0.4 } }

#declare U = union { sphere { 0, 1 } sphere { <2, 0, 0>, 1 } rotate 45*z rotate -45*z translate <-3.5, 0, 0> };
object { U pigment { rgb <0.9, 0.6, 0.2> } }
sphere { min_extent(U), 0.2 pigment { rgb <1, 0, 0> } }
sphere { max_extent(U), 0.2 pigment { rgb <0, 1, 0> } }

// the box of a union of a rotated union, rotated again
#declare V = union { object { U translate <3.5, 0, 0> } box { 0, 0.5 } rotate 30*y translate <1, 0, 0> };
object { V pigment { rgb <0.3, 0.7, 0.9> } }
sphere { min_extent(V), 0.2 pigment { rgb <1, 0, 1> } }
sphere { max_extent(V), 0.2 pigment { rgb <1, 1, 0> } }

// text centred by its extents, as the sample scenes do it
#declare T = union { text { ttf "cyrvetic.ttf" "Ab" 0.2, 0 } sphere { 0, 0.05 } rotate 40*z rotate -40*z };
object { T translate -(min_extent(T) + (max_extent(T) - min_extent(T)) / 2) scale 1.5 translate <0, 2.8, 0> pigment { rgb 1 } }
