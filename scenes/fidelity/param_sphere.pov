// povml fidelity scene: param_sphere
// Rule: contained_by sphere: the ray taken into the surface's space and renormalised for the
//       sphere, its depths divided back; the search starts 4 accuracies beyond the entry (from
//       0 when the ray starts inside); bare function bodies (no 'function' keyword: POV-Ray's
//       Parse_FunctionContent starts after the token its EXPECT took, here the leading 0) and
//       the corners given in reverse order (sorted); accuracy and max_gradient set.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
#declare R = 0.8;
parametric {
  0 cos(u)*sin(v)*R, 0 cos(v)*R, function { sin(u)*sin(v)*R }
  <2*pi, pi>, <0, 0>
  contained_by { sphere { 0, 0.85 } }
  accuracy 0.004 max_gradient 1.2
  pigment { rgb <0.3, 0.6, 0.9> } finish { phong 0.6 }
  translate <-1, 0, 0>
}
parametric {
  function { u }, function { 0.3*sin(3*u)*cos(2*v) }, function { v }
  <-0.9, -0.9>, <0.9, 0.9>
  contained_by { sphere { 0, 1.3 } }
  accuracy 0.005 max_gradient 2
  pigment { rgb <0.9, 0.8, 0.3> }
  rotate <-30, 20, 0> translate <1.1, 0, 0>
}
plane { y, -1 pigment { rgb <0.8, 0.8, 0.75> } }
