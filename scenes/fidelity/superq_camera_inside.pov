// povml fidelity scene: superq_camera_inside
// Rule: the camera's starting interiors come from each shape's Inside at the camera: a glass
//       superellipsoid, ovus and sphere sweep (linear and cubic) each around the camera bend
//       the primary rays by their ior from the start (Superellipsoid::Inside, Ovus::Inside,
//       SphereSweep::Inside).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -3> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
sphere { <0, 0.6, 1.5>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } }
superellipsoid { <0.4, 0.4> scale 0.6 translate <0, 1, -3> pigment { rgbf <1, 1, 1, 0.95> } interior { ior 1.2 } }
ovus { 0.8, 0.5 translate <0, 0.5, -3> pigment { rgbf <1, 1, 1, 0.95> } interior { ior 1.1 } }
sphere_sweep { linear_spline 2, <-1, 1, -3>, 0.3, <1, 1, -3>, 0.4 pigment { rgbf <1, 1, 1, 0.95> } interior { ior 1.15 } }
sphere_sweep { cubic_spline 4, <0, 0, -4>, 0.2, <0, 1, -3.2>, 0.35, <0, 1, -2.8>, 0.35, <0, 2, -2>, 0.2 pigment { rgbf <1, 1, 1, 0.95> } interior { ior 1.05 } }
