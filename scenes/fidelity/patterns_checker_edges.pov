// povml fidelity scene: patterns_checker_edges
// Rule: checker takes floor(c + 1e-10) per coordinate, so a coordinate on a cell boundary, or a
//       rounding error below it, belongs to the cell above (docs/povray-rules.md §17.4).
// The camera looks straight down from height 10 with right 1.6 and up 1.2: pixel centre rays
// cross the plane at x = (i + 1)/10 − 8 and z = 6 − j/10, so every tenth column and row lands
// on a whole coordinate, up to the rounding of the ray.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.05, 10, 0.05> direction <0, -1, 0> up <0, 0, 1.2> right <1.6, 0, 0> }
light_source { <0, 20, 0> color rgb 1 }
plane { y, 0 pigment { checker rgb 1, rgb <0.2, 0, 0> } finish { ambient 1 diffuse 0 } }
