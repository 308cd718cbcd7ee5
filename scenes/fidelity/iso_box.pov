// povml fidelity scene: iso_box
// Rule: isosurface in its default container box { -1, 1 } (isosurf.cpp): the interval search
//       with max_gradient, the accuracy, the cache of the last missed segment (carried from ray
//       to ray: +WT1), the normal by forward differences; a closed container shows where the
//       function is negative on its faces.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1.5, 2.2, -3.5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
isosurface {
  function { x*x + y*y + z*z - 1.2 + 0.3*sin(4*x)*cos(3*z) }
  max_gradient 3.5
  pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.5 }
}
plane { y, -1.01 pigment { checker rgb 1 rgb <0.5, 0.6, 0.5> } }
