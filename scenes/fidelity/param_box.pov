// povml fidelity scene: param_box
// Rule: the parametric surface (fpmetric.cpp): a torus x = cos u (1 + r cos v), y = r sin v,
//       z = sin u (1 + r cos v) within contained_by box; the (u, v) rectangle subdivided along
//       its longer side until a piece is smaller than accuracy (0.001 by default), each piece's
//       x, y, z bounded from its corners by max_gradient 1 (less the accuracy); the crossing is
//       the near depth of the z slab; the normal from steps of accuracy in u and v.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -4> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
parametric {
  function { cos(u)*(1 + 0.35*cos(v)) },
  function { 0.35*sin(v) },
  function { sin(u)*(1 + 0.35*cos(v)) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } }
  pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.5 }
}
plane { y, -1 pigment { rgb <0.8, 0.8, 0.75> } }
