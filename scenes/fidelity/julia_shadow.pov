// povml fidelity scene: julia_shadow
// Rule: shadow rays meet the fractal's first crossing only (outside CSG); a spotlight from the
//       side throws the fractal's shadow across the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -3.2> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.4,0.4,0.5> } }
light_source { <3, 6, 2>, rgb 0.8 spotlight point_at <0, 0, 0> radius 20 falloff 30 }
julia_fractal { <-0.45, 0.1, 0.3, 0.0> max_iteration 7 precision 20 scale 1.2
  pigment { rgb <1, 0.8, 0.4> } finish { specular 0.5 } }
