// povml fidelity scene: split_union_interior
// Rule: a top-level union is split into its members (Split_Unions, no bounded_by), and the members
//       that have no interior of their own still SHARE the union's one interior: where a glass
//       cylinder stands in the top of a glass box, a ray inside the cylinder that crosses the box's
//       top has not entered a second medium but left the only one (total internal reflection at
//       a grazing angle), as for a union kept whole (§16.5). Left: the interior on the union;
//       middle: on an outer union holding an inner one (both split, one interior); right: the
//       box has an interior of its own, a second medium.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 20 }
camera { location <0, 5, -20> angle 40 right x*image_width/image_height look_at <0, 1, 0> }
light_source { <0, 43, -25>, rgb 0.6 }
plane { y, -1 pigment { checker rgb <0.1, 0.5, 0.2>, rgb <0.7, 0.8, 1> scale <32000, 1, 2> } finish { ambient 0.1 diffuse 0.6 } }
#declare Glass = texture { pigment { rgbf <1, 1, 1, 0.7> } finish { ambient 0 diffuse 0 phong 0.8 } }
union {
  box { <-1, -1, -1>, <1, 1.001, 1> }
  cylinder { y, 3 * y, 1 }
  texture { Glass } interior { ior 1.5 }
  translate -3 * x
}
union {
  union { box { <-1, -1, -1>, <1, 1.001, 1> } }
  cylinder { y, 3 * y, 1 }
  texture { Glass } interior { ior 1.5 }
}
union {
  box { <-1, -1, -1>, <1, 1.001, 1> interior { ior 1.5 } }
  cylinder { y, 3 * y, 1 }
  texture { Glass } interior { ior 1.5 }
  translate 3 * x
}
