// povml fidelity scene: julia_csg
// Rule: in CSG the march goes on past the first crossing (IS_CHILD_OBJECT), its later depths
//       lagging as POV-Ray's do; Inside is the iteration staying in the set; inverse toggles
//       the fractal's own flag (Fractal::Invert), which a later transform clears (the last
//       difference is then an intersection). Near-convex fractals: see docs/julia.md on the
//       later crossings' lagging depths.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -3.2> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.4,0.4,0.5> } }
difference {
  julia_fractal { <-0.2, 0.1, -0.1, 0.05> max_iteration 8 precision 15 }
  box { <-2, 0.1, -2>, <0, 2, 0> }
  pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.5 }
  translate <0.3, 0, 0>
}
intersection {
  julia_fractal { <-0.3, 0.1, 0.2, 0.0> max_iteration 7 precision 20 }
  sphere { <0, 0, -0.3>, 0.9 }
  scale 0.6 translate <-1.2, -0.5, -0.8> pigment { rgb <0.3, 0.9, 0.5> }
}
difference {
  box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> }
  julia_fractal { <-0.45, 0.1, 0.3, 0.0> max_iteration 7 precision 20 scale 0.8 }
  translate <1.3, -0.5, -0.9> pigment { rgb <0.9, 0.3, 0.9> }
}
