// povml fidelity scene: conserve_energy
// Rule: with conserve_energy the transmitted light is scaled by min(1, 1 - refl) per channel
//       (filCol *= 1 - refl) (docs/povray-rules.md §5.2, §6.5).
// Left: glass with reflection 0.5, no conserve_energy (too bright). Middle: the same with
// conserve_energy. Right: reflection { 0.05, 1 fresnel } conserve_energy with ior 1.5.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.4, -6> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.4, 0.55, 0.8> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.1, 1.0, 0>, 0.85 pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 reflection 0.5 } interior { ior 1.5 } }
sphere { < 0.0, 1.0, 0>, 0.85 pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 reflection 0.5 conserve_energy } interior { ior 1.5 } }
sphere { < 2.1, 1.0, 0>, 0.85 pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 reflection { 0.05, 1 fresnel } conserve_energy } interior { ior 1.5 } }
sphere { <-1.0, 0.58, 3.0>, 0.5 pigment { rgb <0.9, 0.3, 0.1> } }
sphere { <1.1, 0.58, 3.0>, 0.5 pigment { rgb <0.2, 0.7, 0.9> } }
plane { y, 0 pigment { rgb <0.9, 0.85, 0.6> } }
