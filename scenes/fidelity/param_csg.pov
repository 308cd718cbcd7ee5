// povml fidelity scene: param_csg
// Rule: a parametric surface has no inside (Inside is false, Invert does nothing): in an
//       intersection only its own crossings inside the box remain (the box's are never inside
//       it); in a difference likewise: the sphere's crossings are never inside the (not)
//       inverted surface, only the surface's crossings within the sphere are seen; POV-Ray
//       warns "Patch objects not allowed in intersection." for both; a union keeps its
//       crossing; clipped_by keeps the one crossing found only inside the clip.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
#declare Torus = parametric {
  function { cos(u)*(1 + 0.35*cos(v)) },
  function { 0.35*sin(v) },
  function { sin(u)*(1 + 0.35*cos(v)) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } }
  accuracy 0.004
}
intersection {
  object { Torus }
  box { <-1.5, -0.5, -0.4>, <0.4, 0.5, 1.5> }
  scale 0.6 translate <-1.3, 0.5, 0> pigment { rgb <0.9, 0.6, 0.3> }
}
difference {
  sphere { 0, 0.9 }
  object { Torus scale 0.8 }
  translate <1.3, 0.5, 0> pigment { rgb <0.3, 0.8, 0.5> }
}
union {
  object { Torus scale 0.5 }
  sphere { 0, 0.3 }
  translate <0, -0.4, -1.2> pigment { rgb <0.5, 0.5, 0.95> }
}
object { Torus clipped_by { plane { x, 0.2 } } scale 0.5 rotate -90*x translate <0, 0.9, 0.8> pigment { rgb <0.9, 0.9, 0.9> } }
plane { y, -1 pigment { rgb <0.8, 0.8, 0.75> } }
