// povml fidelity scene: param_precompute
// Rule: precompute depth, x, y, z: the bounds of the chosen functions over the first depth - 1
//       levels of halving (pieces 1 ... 2^depth - 1, numbered as the search numbers them) taken
//       from the table, the others evaluated; a Moebius strip with all three (depth 15), a
//       wave sheet with y and z only (depth 16), whose max_gradient is far too small: the
//       table's bounds (joined from the finest level) keep pieces the evaluated ones lose.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
parametric {
  function { cos(u)+v*cos(u/2)*cos(u) }
  function { sin(u)+v*cos(u/2)*sin(u) }
  function { v*sin(u/2) }
  <0, -0.3>, <2*pi, 0.3>
  contained_by { box { <-2, -2, -2>, <2, 2, 2> } }
  accuracy 0.002
  precompute 15, x, y, z
  rotate <-25, 0, 0> scale 0.8 translate <-1.1, 0, 0>
  pigment { rgb 1 } finish { specular 0.4 }
}
parametric {
  function { u } function { 0.12*sin(10*u)*sin(8*v) } function { v }
  <-1, -1>, <1, 1>
  contained_by { box { <-1, -0.3, -1>, <1, 0.3, 1> } }
  accuracy 0.003 max_gradient 0.05
  precompute 16 y, z
  translate <1.1, -0.3, 0>
  pigment { rgb <0.4, 0.9, 0.5> }
}
plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.75> } }
