// povml fidelity scene: quadric_glass
// Rule: glass quadrics (docs/povray-rules.md §6.2, §6.4): a ray refracts into a quadric solid and out
//       again, its interior entered and left by the crossings of one surface; the roots of a ray
//       starting on the surface (≈ 0) fall under 1e-6 or the 1e-4 of every ray (§2.1); filtered
//       shadows through them (§4); the glass paraboloid and the unbounded cylinder are tested by
//       every ray.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, -5.5> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.25, 0.35, 0.55> }
light_source { <-3, 6, -5>, rgb 1 }
// a glass ellipsoid
quadric { <1.5, 4, 2.5>, <0, 0, 0>, <0, 0, 0>, -1
  pigment { rgbf <0.95, 0.98, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.8 reflection 0.05 }
  interior { ior 1.5 fade_distance 2 fade_power 1 }
  translate <-1.1, 0.55, -0.5> }
// a green glass cylinder along z, closed by a box
intersection {
  quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -0.16 }
  box { <-1, -1, -0.6>, <1, 1, 0.6> }
  pigment { rgbt <0.8, 1, 0.8, 0.8> } finish { ambient 0 diffuse 0.1 } interior { ior 1.5 }
  rotate y*30 translate <0.9, 0.45, -1.2> }
// a glass paraboloid bowl cut by the plane y = 1 (a quadric half-space)
intersection {
  quadric { <3, 0, 3>, <0, 0, 0>, <0, -1, 0>, 0 }
  quadric { <0, 0, 0>, <0, 0, 0>, <0, 1, 0>, -1 }
  pigment { rgbf <1, 0.9, 0.8, 0.85> } finish { ambient 0 diffuse 0.05 phong 0.5 } interior { ior 1.33 }
  translate <0.4, 0.05, 0.6> }
box { <-2, 0, 1.5>, <-1, 2, 2> pigment { rgb <0.9, 0.2, 0.2> } }
box { <-0.5, 0, 1.5>, <0.5, 2, 2> pigment { rgb <0.2, 0.9, 0.2> } }
box { <1, 0, 1.5>, <2, 2, 2> pigment { rgb <0.2, 0.2, 0.9> } }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.5, 0.5, 0.5> } }
