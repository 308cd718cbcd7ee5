// povml fidelity scene: interior_fade
// Rule: interior fade on the segment travelled inside an object. Camera/refracted rays (applied at
//       the exit surface): factor fade_colour + (1-fade_colour)/(1+(d/fade_distance)^fade_power), or
//       exp(-(1-fade_colour)d/fade_distance) for fade_power >= 1000, applied whenever
//       fade_distance != 0 (fade_power 0 gives a constant 1/2 for black). Shadow rays apply it only
//       when fade_power > 0 (docs/povray-rules.md §6.3, §4, pitfalls §13.9, §13.11).
// Left: ior 1.0, fade_distance 0.8 fade_power 2 fade_color rgb <0.2,0.5,1> (blue-ish core, tinted shadow).
// Middle: ior 1.3, fade_distance 1 fade_power 1001 (exponential) fade_color rgb <1,0.35,0.2>.
// Right: ior 1.0, fade_distance 0.5, no fade_power: camera rays halved, shadow NOT faded.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.7, 0.75, 0.8> }
light_source { <1, 9, -3>, rgb 1 }
sphere { <-2.2, 1.0, 0>, 0.85 pigment { rgbt <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0.05 } interior { ior 1.0 fade_distance 0.8 fade_power 2 fade_color rgb <0.2, 0.5, 1> } }
sphere { < 0.0, 1.0, 0>, 0.85 pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0.05 } interior { ior 1.3 fade_distance 1 fade_power 1001 fade_color rgb <1, 0.35, 0.2> } }
sphere { < 2.2, 1.0, 0>, 0.85 pigment { rgbt <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0.05 } interior { ior 1.0 fade_distance 0.5 } }
sphere { <0.0, 0.58, 3.0>, 0.5 pigment { rgb <0.9, 0.8, 0.1> } }
plane { y, 0 pigment { rgb <0.95, 0.95, 0.9> } }
