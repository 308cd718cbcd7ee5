// povml fidelity scene: iso_evaluate
// Rule: evaluate P0, P1, P2: max_gradient lowered by P2 at each search above P0, raised to
//       gradient·P1² where an interval shows more than max_gradient/P1, kept in the object from
//       ray to ray (+WT1); POV-Ray's "Evaluate found a maximum gradient of …" at the end.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -3.5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
isosurface {
  function { x*x + y*y + z*z - 0.8 + 0.15*sin(6*x)*sin(6*z) }
  contained_by { box { -1, 1 } }
  max_gradient 1.0
  evaluate 1, 1.4, 0.9
  pigment { rgb <0.5, 0.9, 0.5> } finish { phong 0.5 }
}
plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.75> } }
