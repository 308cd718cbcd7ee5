// povml course scene 03 -- slide "Correcting for Non-Visible Lights", the note:
// "consider your intersection points along the ray L carefully -- Hint: they might be beyond the light!"
// Shows: the light hangs at y = 2 between the floor and a large ball above it. Shadow feelers from
// the floor toward the light would hit that ball if they were not stopped at the light, which
// would wrongly darken the whole floor. Only hits with t < distance to the light count, so the floor
// is lit and only the small ball (really between light and floor) casts a shadow.
// (docs/povray-rules.md §4: 1e-3 < t < dist - 1e-3.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.6, 0> right x*image_width/image_height }
background { rgb <0.05, 0.05, 0.1> }
light_source { <0, 2, 0>, rgb 1 }
sphere { <0, 4.2, 0.5>, 1.4 pigment { rgb <0.9, 0.7, 0.2> } finish { phong 0.5 } }
sphere { <-1.2, 1.0, 0.2>, 0.35 pigment { rgb <0.3, 0.5, 0.9> } finish { phong 0.5 } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.8> } }
