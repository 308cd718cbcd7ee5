// povml fidelity scene: julia_basic
// Rule: the quaternion julia fractal z -> z^2 + c (fractal.cpp, quatern.cpp): the march by the
//       distance estimate from the bounding sphere, the bisection to 1e-7, the normal from the
//       derivative of the iteration; default slice (w = 0), max_iteration 20, precision 20.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -3.2> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
  pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.5 } }
plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.75> } }
