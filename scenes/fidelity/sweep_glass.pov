// povml fidelity scene: sweep_glass
// Rule: refraction through sphere sweeps: the ray inside meets the far wall; the first and last
//       sorted crossings are always kept by Find_Valid_Points.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
sphere_sweep { linear_spline 3, <-2, 0.5, 0>, 0.4, <-1, 1.3, 0>, 0.5, <0, 0.5, 0>, 0.4
  pigment { rgbf <0.95, 0.95, 1, 0.9> } finish { phong 0.9 reflection 0.1 } interior { ior 1.5 } }
sphere_sweep { cubic_spline 5, <0.5, 0.3, 0>, 0.3, <1, 0.5, 0>, 0.4, <1.5, 1.2, 0.3>, 0.4, <2.3, 0.8, 0.5>, 0.3, <2.5, 0.3, 0.5>, 0.2
  pigment { rgbf <1, 0.9, 0.8, 0.85> } finish { specular 0.6 } interior { ior 1.33 } }
sphere { <0, 0.4, 2.5>, 0.4 pigment { rgb <0.9, 0.3, 0.2> } }
