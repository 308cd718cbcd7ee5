// povml fidelity scene: plane_normal_length
// Rule: plane { <n>, d }: n is normalised but d is NOT divided by |n|; the plane is n^.P = d
//       (docs/povray-rules.md §2.3, pitfall §13.14).
// plane { <0,2,0>, 1 } lies at y = 1 (not 0.5): the ball (bottom at y = 1.05) floats just above
// it with a tight shadow. plane { <0,0,-3>, -6 } is the wall z = 6 (not z = 2, which would hide
// the yellow ball at z = 3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 1.4, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.1> }
light_source { <-5, 5, 1>, rgb 1 }
plane { <0, 2, 0>, 1 pigment { rgb <0.7, 0.7, 0.6> } }
plane { <0, 0, -3>, -6 pigment { rgb <0.4, 0.5, 0.8> } }
sphere { <0, 1.5, 0>, 0.45 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { <1.6, 1.6, 3>, 0.5 pigment { rgb <0.9, 0.8, 0.1> } }
