// povml fidelity scene: julia_glass
// Rule: refraction through the fractal needs its Inside and normal: the march from inside
//       steps 2e-7 further first and finds the way out.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -3.2> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.4,0.4,0.5> } }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> max_iteration 8 precision 15
  rotate y*30 pigment { rgbf <0.95, 0.95, 1, 0.9> } finish { phong 0.8 reflection 0.1 } interior { ior 1.5 } }
