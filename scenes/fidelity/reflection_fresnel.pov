// povml fidelity scene: reflection_fresnel
// Rule: reflection { MIN, MAX fresnel } blends with the exact Fresnel term F(n, ci) where n is the
//       relative IOR n_t/n_i from interior { ior }; with `fresnel` and one colour MIN = 0
//       (docs/povray-rules.md §5.1, §5.2 type 1, pitfall §13.12).
// Left: reflection { 0, 1 fresnel } ior 1.5 (weak centre, strong rim).
// Middle: reflection { 1 fresnel } ior 2.5 (MIN set to 0; stronger overall).
// Right: reflection { 0.2, 1 fresnel } with default ior 1 (F = 0, so constant MIN = 0.2).
// Floor: reflection { 0, 1 fresnel } ior 1.33, strong towards the horizon.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.4, 0.6, 0.9> }
light_source { <-3, 6, -5>, rgb 1 }
light_source { <4, 3, 6>, rgb 0.4 }
sphere { <-2.1, 0.9, 0>, 0.85 pigment { rgb <0.6, 0.1, 0.1> } finish { reflection { 0, 1 fresnel } } interior { ior 1.5 } }
sphere { < 0.0, 0.9, 0>, 0.85 pigment { rgb <0.1, 0.5, 0.1> } finish { reflection { 1 fresnel } } interior { ior 2.5 } }
sphere { < 2.1, 0.9, 0>, 0.85 pigment { rgb <0.1, 0.1, 0.6> } finish { reflection { 0.2, 1 fresnel } } }
sphere { < 0.0, 2.2, 4>, 1.0 pigment { rgb <1, 0.8, 0.2> } }
plane { y, 0 pigment { rgb <0.15, 0.15, 0.18> } finish { reflection { 0, 1 fresnel } } interior { ior 1.33 } }
