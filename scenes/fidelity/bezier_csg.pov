// povml fidelity scene: bezier_csg
// Rule: a patch has no inside (Inside is false, Invert does nothing): in a difference it cuts
//       nothing and its own crossings inside the box are kept only where a merge keeps them;
//       a union keeps every crossing; a glass patch refracts as a sheet; shadows on the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.75> rgb <0.4,0.4,0.5> } }
union {
  bicubic_patch { type 1 flatness 0.05 u_steps 3 v_steps 3 <-1.5, 0, -1.5>, <-0.5, 1, -1.5>, <0.5, -1, -1.5>, <1.5, 0, -1.5>,
  <-1.5, 0.5, -0.5>, <-0.5, 1.5, -0.5>, <0.5, 0.5, -0.5>, <1.5, 0, -0.5>,
  <-1.5, -0.5, 0.5>, <-0.5, 0, 0.5>, <0.5, 1.5, 0.5>, <1.5, 0.5, 0.5>,
  <-1.5, 0, 1.5>, <-0.5, -0.5, 1.5>, <0.5, 0.5, 1.5>, <1.5, 0, 1.5> scale 0.5 translate <-1, 0.3, 0> }
  sphere { <-1, 0.3, 0>, 0.3 }
  pigment { rgb <0.9, 0.6, 0.3> }
}
difference {
  box { <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6> }
  bicubic_patch { type 1 flatness 0.05 u_steps 3 v_steps 3 <-1.5, 0, -1.5>, <-0.5, 1, -1.5>, <0.5, -1, -1.5>, <1.5, 0, -1.5>,
  <-1.5, 0.5, -0.5>, <-0.5, 1.5, -0.5>, <0.5, 0.5, -0.5>, <1.5, 0, -0.5>,
  <-1.5, -0.5, 0.5>, <-0.5, 0, 0.5>, <0.5, 1.5, 0.5>, <1.5, 0.5, 0.5>,
  <-1.5, 0, 1.5>, <-0.5, -0.5, 1.5>, <0.5, 0.5, 1.5>, <1.5, 0, 1.5> scale 0.5 inverse }
  translate <1.2, 0, 0> pigment { rgb <0.3, 0.9, 0.5> }
}
merge {
  bicubic_patch { type 0 flatness 0.05 u_steps 3 v_steps 3 <-1.5, 0, -1.5>, <-0.5, 1, -1.5>, <0.5, -1, -1.5>, <1.5, 0, -1.5>,
  <-1.5, 0.5, -0.5>, <-0.5, 1.5, -0.5>, <0.5, 0.5, -0.5>, <1.5, 0, -0.5>,
  <-1.5, -0.5, 0.5>, <-0.5, 0, 0.5>, <0.5, 1.5, 0.5>, <1.5, 0.5, 0.5>,
  <-1.5, 0, 1.5>, <-0.5, -0.5, 1.5>, <0.5, 0.5, 1.5>, <1.5, 0, 1.5> scale 0.4 }
  sphere { 0, 0.35 }
  translate <0, 0.2, -1.5> pigment { rgbf <1, 1, 1, 0.8> } interior { ior 1.3 }
}
