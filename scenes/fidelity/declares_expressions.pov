// povml fidelity scene: declares_expressions
// Rule: scene-language subset: #declare/#local of floats, vectors, colours, pigments, finishes,
//       textures, interiors and objects; float/vector arithmetic with promotion; component access
//       .x .y .z .red .green .blue .filter .transmit; pi, true, false, image_width/image_height;
//       object { Id modifiers } makes a copy whose pigment is edited (docs/povray-rules.md §11.1, §11.2,
//       §11.3, §19.3).
#version 3.7;
#declare Ar = image_width / image_height;
#declare CamPos = <0, 1.5, -6>;
#declare Target = CamPos + <0, -0.7, 6>;
#local Half = 0.5;
#declare R0 = 0.8;
#declare Base = rgb <0.9, 0.5, 0.2>;
#declare Swapped = rgb <Base.blue, Base.red, Base.green>;
#declare Dimmed = Base * Half;
#declare Glass = rgbf <0.9, 1, 0.9, 0.85>;
#declare P1 = pigment { Base };
#declare F1 = finish { phong 0.6 phong_size 30 };
#declare T1 = texture { pigment { Swapped } finish { F1 } };
#declare I1 = interior { ior 1.3 };
#declare Ball = sphere { <0, 0, 0>, R0 texture { T1 } };
#declare Lift = <0, R0 + 0.1, 0>;
/* nested /* block */ comment */
global_settings { assumed_gamma 1.0 max_trace_level 5 + 1 }
camera { location CamPos look_at Target right x*Ar }
light_source { CamPos + <-3, 4.5, 1>, rgb <1, 1, 1> * (true + false) }
object { Ball translate Lift + <-2.2, 0, 0> }
object { Ball translate <0, Lift.y * 1.5, 1.5> pigment { Dimmed } }
sphere { <2.2, 0, 0>, R0 pigment { P1 } finish { F1 } translate Lift }
sphere { <1.0, 0.5, -2.0>, pi / 8 pigment { rgbf <1, Glass.green, Glass.red, Glass.filter> } finish { phong 1 } interior { I1 } }
sphere { <-0.9, 0.4, -2.2>, 0.3 pigment { rgbt <Base.red, Base.green, Base.blue, Glass.transmit + 0.5> } }
plane { y, -(0.1 + 0.1) pigment { rgb <0.6, 0.6, 0.6> * (1 + 1/3) * 0.9 } }
