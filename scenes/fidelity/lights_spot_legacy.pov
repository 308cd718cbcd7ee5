// povml fidelity scene: lights_spot_legacy
// Rule: spotlights and the object flags in a scene without #version (legacy, no gamma): the same
//       attenuation and ray categories (docs/povray-rules.md §18.2, §16.6, §8.2).
camera { location <0, 5, -7> look_at <0, 0.3, 0> }
background { rgb <0.1, 0.15, 0.25> }
light_source { <1, 6, -3>, rgb 1.3 spotlight radius 18 falloff 28 tightness 10 point_at <0, 0, 0.5> }
light_source { <-6, 8, -6>, rgb 0.2 }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } finish { reflection 0.3 } }
sphere { <-1.2, 0.6, 0.4>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.8 phong_size 40 } no_reflection }
sphere { <1.1, 0.5, -0.3>, 0.5 pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.5 } no_image }
box { <-0.3, 0, 1.2>, <0.5, 1.1, 2> pigment { rgb <0.4, 0.8, 0.3> } }
