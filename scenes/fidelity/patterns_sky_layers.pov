// povml fidelity scene: patterns_sky_layers
// Rule: several sky pigments are layered from the last written down, then the background
//       shows through their filter and transmit (docs/povray-rules.md §18.1, 3.7 formula).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at <0, 1.5, 0> right x*image_width/image_height angle 80 }
background { rgb <0.1, 0.6, 0.1> }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.9, 0.7, 0.5>] [1 rgbt <0.05, 0.1, 0.4, 0.5>] } }
  pigment { checker rgbt <1, 1, 1, 0.6>, rgbf <0.2, 0.3, 1, 0.7> scale 0.2 }
  pigment { gradient x color_map { [0 rgbt <1, 0, 0, 1>] [0.5 rgbft <1, 0.5, 0, 0.3, 0.3>] [1 rgbt 1] } }
  emission 0.9
}
sphere { <0, 1, 0>, 1 finish { reflection 0.5 } pigment { rgb 0.3 } }
