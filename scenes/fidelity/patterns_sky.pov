// povml fidelity scene: patterns_sky
// Rule: sky_sphere pigments are evaluated at the unit ray direction taken as a point (the
//       sky's translate shifts it); a gradient y sky wraps below the horizon (docs/povray-rules.md §18.1,
//       §17.5).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at <0, 1.5, 0> right x*image_width/image_height angle 80 }
light_source { <3, 9, -6> color rgb 1 }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.9, 0.7, 0.5>] [0.3 rgb <0.3, 0.5, 0.9>] [1 rgb <0.05, 0.1, 0.4>] } }
  translate <0, -0.1, 0> rotate <0, 0, 10>
}
sphere { <0, 1, 0>, 1 finish { reflection 0.5 } pigment { rgb 0.3 } }
