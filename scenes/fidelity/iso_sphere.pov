// povml fidelity scene: iso_sphere
// Rule: contained_by { sphere }: the container met by the renormalised ray in isosurface space,
//       its depths scaled back; where the function is negative on the sphere the sphere is
//       surface, with the sphere's normal; translated and scaled container centre.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
isosurface {
  function { abs(x) + abs(y) + abs(z) - 1.3 }
  contained_by { sphere { <0.1, 0, 0>, 1.05 } }
  max_gradient 1.8
  accuracy 0.0005
  pigment { rgb <0.4, 0.7, 0.9> } finish { specular 0.4 }
}
plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.75> } }
