// povml fidelity scene: emission_ambient
// Rule: ambient and emission are colours; ambient is multiplied by global ambient_light (colour),
//       emission is not; both are multiplied by the pigment and att (docs/povray-rules.md §3.2, §10.2).
// global ambient_light is bluish. Left: ambient colour only (diffuse 0). Middle: emission colour
// plus diffuse. Right: emission 1 diffuse 0 (a self-lit ball that lights nothing else).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <0.6, 0.8, 1.0> }
camera { location <0, 1.2, -6> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.02, 0.02, 0.02> }
light_source { <-4, 6, -5>, rgb <0.8, 0.8, 0.8> }
sphere { <-2.2, 0.8, 0>, 0.9 pigment { rgb <1, 0.9, 0.8> } finish { ambient rgb <0.5, 0.2, 0.1> diffuse 0 } }
sphere { <0, 0.8, 0>, 0.9 pigment { rgb <0.6, 0.9, 0.6> } finish { ambient 0 emission rgb <0.1, 0.4, 0.2> diffuse 0.5 } }
sphere { <2.2, 0.8, 0>, 0.9 pigment { rgb <1, 0.7, 0.3> } finish { ambient 0 emission 1 diffuse 0 } }
plane { y, -0.2 pigment { rgb 0.6 } finish { ambient 0.3 diffuse 0.4 } }
