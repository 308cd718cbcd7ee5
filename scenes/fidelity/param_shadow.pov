// povml fidelity scene: param_shadow
// Rule: a parametric surface casts shadows (on the floor, on a sphere, on itself) and is
//       shadowed: shadow rays meet its one crossing between the point and the light; the
//       shadow cache keeps it; no_shadow on a second copy.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -5> look_at <0, -0.3, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-3, 8, -2>, rgb 1 }
light_source { <6, 3, -4>, rgb 0.4 }
#declare Wave = parametric {
  function { u }, function { 0.15*sin(5*u)*cos(4*v) }, function { v }
  <-1, -1>, <1, 1>
  contained_by { box { <-1, -0.2, -1>, <1, 0.2, 1> } }
  accuracy 0.004
}
object { Wave rotate <20, 0, -15> translate <-0.6, 0.2, 0> pigment { rgb <0.9, 0.5, 0.3> } }
object { Wave scale 0.4 translate <1.4, 0.6, -0.5> pigment { rgb <0.4, 0.9, 0.4> } no_shadow }
sphere { <0.2, -0.6, 0.4>, 0.4 pigment { rgb <0.9, 0.9, 0.95> } }
plane { y, -1 pigment { rgb <0.8, 0.8, 0.75> } }
