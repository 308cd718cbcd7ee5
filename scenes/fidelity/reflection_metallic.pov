// povml fidelity scene: reflection_metallic
// Rule: reflection { .. metallic M } scales refl per channel by 1 + M(1-F)(C.rgb - 1), F the
//       empirical function of acos(ci); `metallic` without a value is 1 (docs/povray-rules.md §5.1, §5.2).
// All three balls have a copper pigment. Left: reflection 0.8 (neutral mirror). Middle:
// reflection { 0.8 metallic } (copper-tinted reflection). Right: reflection { 0.8 metallic 0.5 }.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.6, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.6, 0.7, 0.9> }
light_source { <-3, 6, -5>, rgb 1 }
#declare Copper = rgb <0.85, 0.45, 0.25>;
sphere { <-2.1, 0.9, 0>, 0.85 pigment { Copper } finish { ambient 0.05 diffuse 0.2 reflection 0.8 } }
sphere { < 0.0, 0.9, 0>, 0.85 pigment { Copper } finish { ambient 0.05 diffuse 0.2 reflection { 0.8 metallic } } }
sphere { < 2.1, 0.9, 0>, 0.85 pigment { Copper } finish { ambient 0.05 diffuse 0.2 reflection { 0.8 metallic 0.5 } } }
sphere { < 0.0, 0.35, -1.7>, 0.3 pigment { rgb <0.2, 0.9, 0.9> } }
plane { y, 0 pigment { rgb <0.9, 0.9, 0.9> } }
