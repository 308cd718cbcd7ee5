// povml fidelity scene: gamma_1_0
// Rule: language version and gamma mode decide the output transfer curve (docs/povray-rules.md §8.1, §8.2,
//       pitfall §13.1). The four gamma_* scenes share the same geometry; only the header differs.
// Mode: `#version 3.7; assumed_gamma 1.0`: linear working space, exact piecewise sRGB output (§8.1).
// Content: a grey ramp (rgb 0.05, 0.2, 0.45, 0.8) plus a filtered red ball rgbf <0.8,0.3,0.3,0.6>
// (att 0.4 in 3.7 mode, 0.52 in legacy mode) over a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -5.5> look_at <0, 0.5, 0> right x*image_width/image_height }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.4, 0.6, 0>, 0.5 pigment { rgb 0.05 } finish { ambient 0.2 diffuse 0.6 } }
sphere { <-1.2, 0.6, 0>, 0.5 pigment { rgb 0.2 } finish { ambient 0.2 diffuse 0.6 } }
sphere { < 0.0, 0.6, 0>, 0.5 pigment { rgb 0.45 } finish { ambient 0.2 diffuse 0.6 } }
sphere { < 1.2, 0.6, 0>, 0.5 pigment { rgb 0.8 } finish { ambient 0.2 diffuse 0.6 } }
sphere { < 2.4, 0.6, 0>, 0.5 pigment { rgbf <0.8, 0.3, 0.3, 0.6> } finish { ambient 0.2 diffuse 0.6 phong 0.5 } }
sphere { < 0.0, 0.9, 2.5>, 0.8 pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.6 } }
plane { y, 0 pigment { rgb <0.6, 0.55, 0.45> } }
