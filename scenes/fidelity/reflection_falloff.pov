// povml fidelity scene: reflection_falloff
// Rule: reflection { MIN, MAX falloff F }: frac = (1 - ci)^F, refl = frac*MAX + (1-frac)*MIN,
//       ci = -D.N; child weight = weight * max(MAX, MIN) (docs/povray-rules.md §5.1, §5.2 type 0).
// Left: reflection { 0.05, 0.95 falloff 3 } (weak in the centre, mirror-like at the rim).
// Middle: reflection { 0.1, 0.6 } (falloff 1). Right: reflection 0.5 (old syntax, constant).
// Small coloured balls and the two-colour floor give something to reflect.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.6, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.35, 0.55, 0.85> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.1, 0.9, 0>, 0.85 pigment { rgb <0.1, 0.1, 0.12> } finish { reflection { 0.05, 0.95 falloff 3 } } }
sphere { < 0.0, 0.9, 0>, 0.85 pigment { rgb <0.1, 0.1, 0.12> } finish { reflection { 0.1, 0.6 } } }
sphere { < 2.1, 0.9, 0>, 0.85 pigment { rgb <0.1, 0.1, 0.12> } finish { reflection 0.5 } }
sphere { <-1.0, 0.35, -1.6>, 0.3 pigment { rgb <1, 0.8, 0.1> } }
sphere { < 1.1, 0.35, -1.5>, 0.3 pigment { rgb <0.9, 0.1, 0.6> } }
sphere { < 0.0, 2.6, 2.5>, 0.6 pigment { rgb <0.1, 0.9, 0.3> } }
plane { y, 0 pigment { rgb <0.8, 0.5, 0.3> } }
