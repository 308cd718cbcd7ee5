// povml fidelity scene: finish_irid
// Rule: irid { amount thickness turbulence } tints each light's diffuse and highlights and the
//       reflected colour by a thin film's interference over the irid wavelengths
//       (trace.cpp ComputeIridColour); irid_wavelength in global_settings changes them.
#version 3.7;
global_settings { assumed_gamma 1.0 irid_wavelength rgb <0.25, 0.18, 0.14> }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
light_source { <3, 3, -4>, rgb 0.5 shadowless }
plane { y, 0 pigment { checker rgb 0.9, rgb <0.3, 0.4, 0.6> } finish { irid { 0.3 thickness 0.5 } } }
sphere { <-1.1, 1, 0.5>, 1 pigment { rgb <0.6, 0.6, 0.7> } finish { phong 0.8 reflection 0.3 irid { 0.5 thickness 0.4 turbulence 0.6 } } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.9, 0.5, 0.2> } finish { specular 0.6 irid { 0.35 thickness 1.2 } } }
