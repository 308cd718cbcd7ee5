// povml fidelity scene: patterns_legacy_filter
// Rule: without #version, a transparent map colour uses the legacy att formula and filtered
//       shadows walk through the patterned sphere (docs/povray-rules.md §3.2, §17.8, §4).
camera { location <0, 3, -6> look_at <0, 1, 0> }
light_source { <2, 8, -3> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.6 } }
sphere { <0, 1.2, 0>, 1.2
  pigment { gradient y color_map { [0 rgbt <1, 0.2, 0.2, 0.7>] [0.4 rgbf <0.2, 1, 0.2, 0.9>] [0.6 rgb <0.2, 0.2, 1>] [1 rgbft <1, 1, 0, 0.5, 0.3>] } }
  finish { phong 0.8 } }
