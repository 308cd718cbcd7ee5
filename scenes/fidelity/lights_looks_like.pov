// povml fidelity scene: lights_looks_like
// Rule: looks_like { OBJECT modifiers }: the object is written about the origin, moved to the
//       light's centre, then its own modifiers apply; the light's later transforms move both; the
//       object casts no shadow (not even on its own light's rays) and is seen by camera and
//       reflection rays, shaded as usual (docs/povray-rules.md §19.2). In a union the union's pigment
//       reaches an untextured looks_like object and the union's transforms move light and object
//       (§19.1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
light_source {
  <0, 2.2, 0>, rgb 1
  looks_like { sphere { 0, 0.35 pigment { rgb <1, 0.9, 0.6> } finish { ambient 1 diffuse 0 } } scale <1, 1.3, 1> }
  translate <-1, 0, 0.5>
}
union {
  light_source { <0, 3, 0>, rgb 0.5 spotlight radius 15 falloff 25 point_at 0 looks_like { box { -0.2, 0.2 rotate <0, 45, 0> } } }
  sphere { <0, 0.25, -1>, 0.25 }
  pigment { rgb <0.4, 0.9, 0.5> }
  finish { ambient 0.8 }
  translate <1.5, 0, 0>
}
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } finish { reflection 0.3 } }
sphere { <0, 0.5, 0.5>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <-2.5, 0, 1.5>, <-1.8, 1.4, 2.2> pigment { rgb <0.3, 0.6, 0.9> } }
