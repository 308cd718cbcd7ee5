// povml fidelity scene: julia_moved
// Rule: every modifier composes into the fractal's transform (Fractal::Transform); the ray is
//       taken into fractal space with its direction renormalised and the depth scaled back;
//       the normal by MTransNormal. Rotate, non-uniform scale, translate; a cube map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -3.2> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.4,0.4,0.5> } }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> max_iteration 8 precision 15
  rotate <20, 30, 10> scale <1.3, 0.8, 1> translate <0.4, 0, 0.3>
  pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.5 } }
julia_fractal { <-0.2, 0.6, 0.2, 0.0> cube max_iteration 6 precision 30 slice <0,0,1,1>, 0.1
  scale 0.5 translate <-1.1, 0.3, -0.6> pigment { rgb <0.3, 0.7, 1> } }
