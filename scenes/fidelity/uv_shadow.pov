// povml fidelity scene: uv_shadow
// Rule: a shadow ray through a uv-mapped transparent pigment takes its colour at the crossing's
//       UV coordinates (ComputeShadowColour); inside a CSG a member has its own UV coordinates.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
sphere { <0, 0.6, 0>, 0.9
  pigment { uv_mapping checker rgbf <1, 0.2, 0.2, 0.8> rgbf <0.2, 0.2, 1, 0.1> scale <1/12, 1/6, 1> } }
union {
  sphere { <-1.9, 0, 0>, 0.6 }
  box { <1.3, -0.6, -0.6>, <2.5, 0.6, 0.6> }
  pigment { uv_mapping checker rgb <1, 1, 0.2> rgb <0.2, 0.6, 0.2> scale 0.125 }
  rotate y*20
}
plane { y, -1 pigment { rgb 0.8 } }
