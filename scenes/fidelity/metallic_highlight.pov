// povml fidelity scene: metallic_highlight
// Rule: with metallic M the highlight colour is lc * (1 + M(1-F)(C.rgb - 1)), F the empirical
//       Fresnel-like function of acos(N.L); `metallic` alone means 1 (docs/povray-rules.md §3.3, §10.1).
// Back row (phong 1): metallic 0 (white highlight), metallic (=1, gold highlight).
// Front row (specular 0.9 roughness 0.02): metallic 0, metallic 0.6.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.0, -6.5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.05, 0.06, 0.08> }
light_source { <-2, 6, -6>, rgb 1 }
light_source { <5, 2, -3>, rgb <0.6, 0.6, 0.7> }
#declare Gold = rgb <0.9, 0.6, 0.15>;
sphere { <-1.2, 0.8, 1.2>, 0.8 pigment { Gold } finish { ambient 0.05 diffuse 0.5 phong 1 phong_size 20 } }
sphere { < 1.2, 0.8, 1.2>, 0.8 pigment { Gold } finish { ambient 0.05 diffuse 0.5 phong 1 phong_size 20 metallic } }
sphere { <-1.2, 0.5, -1.0>, 0.55 pigment { Gold } finish { ambient 0.05 diffuse 0.5 specular 0.9 roughness 0.02 metallic 0 } }
sphere { < 1.2, 0.5, -1.0>, 0.55 pigment { Gold } finish { ambient 0.05 diffuse 0.5 specular 0.9 roughness 0.02 metallic 0.6 } }
plane { y, -0.2 pigment { rgb <0.35, 0.3, 0.3> } }
