// povml fidelity scene: iso_gradient
// Rule: a max_gradient below the function's gradient: the search misses crossings (holes), the
//       cache answers "no root" for rays near a missed one, and POV-Ray warns at the end of
//       the render with the largest gradient it met ("The maximum gradient found was …").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -3.5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
isosurface {
  function { x*x + y*y + z*z - 0.8 + 0.2*sin(8*x)*sin(8*y) }
  contained_by { box { -1, 1 } }
  max_gradient 1.2
  pigment { rgb <0.8, 0.5, 0.9> }
}
plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.75> } }
