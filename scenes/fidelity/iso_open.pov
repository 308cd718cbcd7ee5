// povml fidelity scene: iso_open
// Rule: open: the container's faces are not surface; a search that starts inside the function
//       turns its sign (Inv3) and finds where the ray leaves it; a wavy sheet cut by its box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -3.5> look_at <0, -0.2, 0> angle 50 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <5, 3, -10>, rgb 0.4 }
isosurface {
  function { y - 0.3*sin(3*x)*sin(3*z) }
  contained_by { box { <-1.5, -1, -1.5>, <1.5, 1, 1.5> } }
  open
  max_gradient 1.5
  pigment { rgb <0.9, 0.8, 0.3> } finish { phong 0.4 }
}
