// povml fidelity scene: coloured_lights
// Rule: each light contributes C*lc*(N.L)*diffuse (+ highlights scaled by lc); lights are summed in
//       parse order; light colours are unbounded (docs/povray-rules.md §3.3).
// Three lights (red, green, blue) from different directions over white objects: the floor shows
// three coloured shadows where one light is blocked (e.g. cyan where red is blocked).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.4, 0> right x*image_width/image_height }
background { rgb 0 }
light_source { <-4, 5, -2>, rgb <0.9, 0, 0> }
light_source { < 0, 6, 3>, rgb <0, 0.8, 0> }
light_source { < 4, 5, -2>, rgb <0, 0, 1.1> }
sphere { <0, 1.0, 0>, 0.8 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.7 phong 0.6 } }
sphere { <-1.8, 0.5, -1.2>, 0.4 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.7 } }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.7 } }
