// povml fidelity scene: lights_ortho_plain
// Rule: orthographic camera without look_at: k1 uses the default look_at <0,0,1>, so the view
//       is 1.33·k1 wide and k1 high (docs/povray-rules.md §18.4).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 1, -3> direction <0, 0, 2> }
background { rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5>, rgb 1 }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } }
sphere { <-1.2, 0.6, 0.4>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.8 phong_size 40 } }
sphere { <1.1, 0.5, -0.3>, 0.5 pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.5 reflection 0.3 } }
box { <-0.3, 0, 1.2>, <0.5, 1.1, 2> rotate <0, 25, 0> pigment { rgb <0.4, 0.8, 0.3> } }
