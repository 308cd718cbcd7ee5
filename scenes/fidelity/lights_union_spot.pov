// povml fidelity scene: lights_union_spot
// Rule: a spotlight inside a union is a global light; the union's rotate and translate move its
//       centre and point_at (docs/povray-rules.md §19.1, §14.8), and object { } copies of a declared
//       parallel light move it too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.3, 0> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
#declare Beam = light_source { <0, 4, 0>, rgb 0.4 parallel point_at <0, 0, 0> }
union {
  light_source { <0, 5, 0>, rgb 1.2 spotlight radius 12 falloff 20 tightness 1 point_at <0, 0, 0> }
  sphere { <0, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } }
  rotate <0, 0, 25>
  translate <0.5, 0, 0.5>
}
object { Beam rotate <30, 0, 0> }
plane { y, 0 pigment { rgb <0.9, 0.88, 0.8> } }
sphere { <-1.6, 0.5, 0.2>, 0.5 pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.5 } }
