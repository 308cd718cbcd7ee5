// povml fidelity scene: tex_interior
// Rule: interior_texture is the texture seen where a ray meets the surface from inside (the
//       normal, inverse counted, points along the ray): the inside of an open cylinder and of a
//       sphere cut open by a difference, and shadow rays crossing them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
cylinder { <-1.1, 0, 0.5>, <-1.1, 1.5, 0.5>, 0.8 open texture { pigment { rgb <0.9, 0.5, 0.1> } } interior_texture { pigment { rgb <0.1, 0.5, 0.9> } } }
difference { sphere { <1, 0.9, 0>, 0.9 } box { <0.5, 0.9, -1>, <2, 2, 1> }
  texture { pigment { rgb <0.2, 0.9, 0.3> } finish { phong 0.5 } }
  interior_texture { pigment { checker rgb <1, 1, 0>, rgbt <1, 0, 0, 0.6> scale 0.2 } } }
