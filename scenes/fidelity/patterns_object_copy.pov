// povml fidelity scene: patterns_object_copy
// Rule: object { S pigment { checker … } } edits the copy's pigment in place: the new pattern
//       keeps the transform of S's pigment, S's object transforms included (docs/povray-rules.md §17.9,
//       §19.3); a union's texture goes to its members in the union's frame (§14.7).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -7> look_at <0, 0.8, 0> right x*image_width/image_height }
light_source { <3, 9, -6> color rgb 1 }
#declare S = sphere { <0, 0, 0>, 1 pigment { checker rgb 1, rgb 0 scale 0.5 } scale 1.2 }
object { S pigment { checker rgb <0, 0, 1>, rgb 1 } translate <-2.2, 1.2, 0> }
object { S translate <0, 1.2, 0> }
union {
  sphere { <2.2, 0.6, -0.6>, 0.6 scale 1.5 }
  sphere { <2.2, 1.8, 0.6>, 0.5 pigment { rgb <0.9, 0.3, 0.1> } }
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.9> scale 0.4 }
  rotate <0, 20, 0>
}
plane { y, 0 pigment { checker rgb 0.8, rgb 0.5 rotate <0, 45, 0> } }
