// povml fidelity scene: patterns_gradient_edges
// Rule: gradient passes values up to 1 unchanged (exactly 1 takes the last entry), maps 2, 3 …
//       and −1, −2 … to 0 (docs/povray-rules.md §17.5, §17.1, §17.2).
// The camera of patterns_checker_edges: pixel centre rays cross the plane on whole x every
// tenth column; the map's first and last colours are far from the middle ones.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.05, 10, 0.05> direction <0, -1, 0> up <0, 0, 1.2> right <1.6, 0, 0> }
light_source { <0, 20, 0> color rgb 1 }
plane { y, 0
  pigment { gradient x color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0.2, 0.2, 0.2>] [1 rgb <0, 0, 1>] } }
  finish { ambient 1 diffuse 0 } }
