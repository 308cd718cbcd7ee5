// povml fidelity scene: quadric_coincident
// Rule: a quadric's Inside includes its surface (left side ≤ 0, Quadric::Inside), and an inverted
//       one, its coefficients negated, includes it too. Here a box's top face and a plane
//       quadric coincide at y = 0.5: which of the two surfaces is kept at each pixel depends on
//       the last bit of each hit point and on ≤ against <, so the speckle must match POV-Ray's
//       exactly (docs/povray-rules.md §16.2: avoid coincident faces; here they are the test).
// Left: intersection { y ≤ 0.5, box }; right: difference { box, y ≥ 0.5 }.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 3, -4> look_at <0, 0.3, 0> right x*image_width/image_height }
light_source { <-5, 9, -6>, rgb 1 }
intersection {
  quadric { <0, 0, 0>, <0, 0, 0>, <0, 1, 0>, -0.5 pigment { rgb <0.9, 0.2, 0.2> } }
  box { <-1, -1, -1>, <1, 0.5, 1> pigment { rgb <0.2, 0.9, 0.2> } }
  translate x*-1.1
}
difference {
  box { <-1, -1, -1>, <1, 0.5, 1> pigment { rgb <0.2, 0.9, 0.2> } }
  quadric { <0, 0, 0>, <0, 0, 0>, <0, -1, 0>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
  translate x*1.1
}
plane { y, -1 pigment { rgb 0.7 } }
