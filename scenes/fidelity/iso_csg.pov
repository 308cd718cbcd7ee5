// povml fidelity scene: iso_csg
// Rule: isosurfaces in CSG: all_intersections (max_trace 10) and max_trace 2 give every
//       crossing along the ray (each search past the last root with the sign turned); a
//       difference keeps the crossings outside the other member by its Inside (the function at
//       most the threshold within the container).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1.5, 2.5, -3.5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
difference {
  isosurface {
    function { x*x + y*y + z*z - 1 }
    contained_by { box { -1.1, 1.1 } }
    max_gradient 2.3
    all_intersections
    pigment { rgb <0.9, 0.6, 0.3> }
  }
  isosurface {
    function { sqrt(x*x + z*z) - 0.45 + 0.1*sin(10*y) }
    contained_by { box { <-0.7, -1.5, -0.7>, <0.7, 1.5, 0.7> } }
    max_gradient 2.1
    max_trace 2
    pigment { rgb <0.3, 0.6, 0.9> }
  }
  box { <0, 0, -2>, <2, 2, 0> pigment { rgb <0.9, 0.9, 0.4> } }
  finish { phong 0.3 }
}
plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.75> } }
