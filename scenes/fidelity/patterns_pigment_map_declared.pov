// povml fidelity scene: patterns_pigment_map_declared
// Rule: a declared pigment_map is copied by pigment_map { Id } and used with waves and transforms
//       like a written one (docs/povray-rules.md §17.3, §17.1).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 1, 0> right x*image_width/image_height }
light_source { <2, 8, -3> color rgb 1 }
#declare PM = pigment_map { [0.2 checker rgb 1, rgb 0 scale 0.3] [0.8 hexagon scale 0.2] }
plane { y, 0 pigment { gradient x pigment_map { PM } scale 3 } }
sphere { <0,1,0>, 1 pigment { gradient y pigment_map { PM } triangle_wave } }
