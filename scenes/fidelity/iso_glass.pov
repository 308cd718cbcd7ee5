// povml fidelity scene: iso_glass
// Rule: an isosurface in glass and casting shadows: refracted rays start inside it (the search
//       from depth 0 with the sign turned when the function is negative there), shadow rays test
//       it without leaving their misses in the cache, Inside decides the interiors.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2, -4> look_at <0, -0.2, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-5, 10, -8>, rgb 1 }
light_source { <6, 6, -4>, rgb 0.4 }
isosurface {
  function { x*x + y*y + z*z - 0.7 + 0.15*sin(5*x)*sin(5*y)*sin(5*z) }
  contained_by { sphere { 0, 1.1 } }
  max_gradient 2.5
  pigment { rgbf <0.9, 0.95, 1, 0.85> } finish { phong 0.8 reflection 0.1 }
  interior { ior 1.4 }
}
isosurface {
  function { y + 1 - 0.05*sin(6*x)*cos(6*z) }
  contained_by { box { <-3, -1.2, -3>, <3, -0.9, 3> } }
  max_gradient 1.4
  pigment { checker rgb 1 rgb <0.5, 0.6, 0.5> }
}
