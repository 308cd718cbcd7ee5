// povml fidelity scene: lights_flags_mirror
// Rule: no_image: not hit by camera rays or what they see through glass, still reflected and
//       still casting shadows; no_reflection: seen directly, casting shadows, but absent from
//       reflections (and from rays refracted after one); no_shadow: seen and reflected but no
//       shadow (docs/povray-rules.md §16.6). A union passes its flags to its members (§16.5).
// Over a mirror floor: a no_image red sphere, a no_reflection blue sphere, a no_shadow green
// sphere, a glass pane through which the no_image sphere's place is seen, and a union whose
// no_reflection reaches both members.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -7> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5>, rgb 1 }
light_source { <5, 6, -3>, rgb 0.3 }
plane { y, 0 pigment { rgb <0.6, 0.6, 0.65> } finish { reflection 0.6 } }
sphere { <-1.8, 0.7, 0>, 0.7 pigment { rgb <0.9, 0.2, 0.2> } no_image }
sphere { <0, 0.7, 0.5>, 0.7 pigment { rgb <0.2, 0.4, 0.9> } finish { phong 0.5 } no_reflection }
sphere { <1.8, 0.7, 0>, 0.7 pigment { rgb <0.2, 0.8, 0.3> } no_shadow }
box { <-2.8, 0.2, -1.6>, <-0.9, 1.6, -1.5> pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1 } }
union {
  sphere { <-0.6, 0.3, -2>, 0.3 pigment { rgb <0.9, 0.8, 0.2> } }
  sphere { <0.6, 0.3, -2>, 0.3 }
  pigment { rgb <0.8, 0.3, 0.8> }
  no_reflection
}
sphere { <0, 2.6, 3>, 0.5 pigment { rgb 1 } finish { reflection 0.8 } no_image off }
