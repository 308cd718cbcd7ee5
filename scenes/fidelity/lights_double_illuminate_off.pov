// povml fidelity scene: lights_double_illuminate_off
// Rule: double_illuminate [bool] on a union sets the value written on the whole subtree when it is
//       read: "double_illuminate off" clears the flag its members set themselves (docs/povray-rules.md
//       §16.5, §16.6; checked: the same scene without the "off" differs in 1214 pixels).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1.2, 0> right x*image_width/image_height }
background { rgb <0.1, 0.15, 0.25> }
light_source { <0, 2, 4>, rgb 1 }
union {
  triangle { <1, 0.2, 1>, <2.8, 0.2, 1>, <1.9, 2.6, 1> double_illuminate }
  triangle { <-1, 0.2, 1>, <0.8, 0.2, 1>, <-0.1, 2.6, 1> double_illuminate }
  pigment { rgb <0.3, 0.6, 0.9> }
  double_illuminate off
}
