// povml fidelity scene: polygon_glass
// Rule: a transparent polygon with an interior (docs/povray-rules.md §6.2, §6.4, §15.7): a ray
//       crossing it enters its interior, ior 1.5, and the next surface met is another object's,
//       so the ray refracts once and goes on inside the polygon's medium; a second polygon
//       crossed later is a second interior; a polygon crossed twice (a folded sheet) is left again
//       (the interior list holds it). Filtered shadows through them (§4). Coloured boxes behind.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, -5.5> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.25, 0.35, 0.55> }
light_source { <-3, 6, -5>, rgb 1 }
polygon { 5, <-1, 0>, <1, 0>, <1, 1.5>, <-1, 1.5>, <-1, 0>
  pigment { rgbf <0.7, 0.85, 1, 0.85> } finish { ambient 0 diffuse 0.05 phong 0.7 reflection 0.05 } interior { ior 1.5 }
  rotate <0, -25, 0> translate <-1, 0.2, -0.6> }
polygon { 5, <-0.7, 0>, <0.7, 0>, <0.7, 1.2>, <-0.7, 1.2>, <-0.7, 0>
  pigment { rgbt <0.9, 1, 0.9, 0.8> } finish { ambient 0 diffuse 0.1 } interior { ior 1.33 }
  rotate <0, 30, 0> translate <1.1, 0.3, -0.8> }
polygon { 5, <-0.7, 0>, <0.7, 0>, <0.7, 1.2>, <-0.7, 1.2>, <-0.7, 0>
  pigment { rgbt <1, 0.9, 0.9, 0.8> } finish { ambient 0 diffuse 0.1 } interior { ior 1.2 }
  rotate <20, 30, 0> translate <1.3, 0.3, 0> }
// a folded sheet: two polygons sharing the union's interior, so the second crossing leaves it
union {
  polygon { 5, <0, 0>, <0.8, 0>, <0.8, 1.3>, <0, 1.3>, <0, 0> rotate y*-40 }
  polygon { 5, <0, 0>, <0.8, 0>, <0.8, 1.3>, <0, 1.3>, <0, 0> rotate y*-140 }
  split_union off
  pigment { rgbf <1, 0.85, 0.7, 0.85> } finish { ambient 0 diffuse 0.05 phong 0.5 } interior { ior 1.5 }
  translate <-0.1, 0.05, -1.9> }
box { <-2, 0, 1.5>, <-1, 2, 2> pigment { rgb <0.9, 0.2, 0.2> } }
box { <-0.5, 0, 1.5>, <0.5, 2, 2> pigment { rgb <0.2, 0.9, 0.2> } }
box { <1, 0, 1.5>, <2, 2, 2> pigment { rgb <0.2, 0.2, 0.9> } }
sphere { <0.3, 0.4, 0.8>, 0.4 pigment { rgb <1, 0.9, 0.3> } }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.5, 0.5, 0.5> } }
