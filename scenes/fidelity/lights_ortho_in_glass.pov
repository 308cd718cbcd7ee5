// povml fidelity scene: lights_ortho_in_glass
// Rule: an orthographic camera's rays each start from their own point of the screen, and each
//       ray's interior list is built from the objects containing that point (docs/povray-rules.md §18.4,
//       §6.4): the screen straddles a glass sphere, so the rays starting inside it refract as
//       they leave, the others enter it from outside.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.8, 1, -1.5> right x*6 up y*4.5 look_at <0.8, 1, 0> }
background { rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5>, rgb 1 }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } }
sphere { <0, 1, -1.5>, 1.4 pigment { rgbf <0.95, 1, 0.95, 0.9> } finish { phong 0.5 } interior { ior 1.5 } }
sphere { <-0.8, 0.6, 2>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <1.2, 0.5, 1.5>, 0.5 pigment { rgb <0.3, 0.6, 0.9> } }
box { <-3, 0, 4>, <3, 3, 4.2> pigment { rgb <0.4, 0.8, 0.3> } }
