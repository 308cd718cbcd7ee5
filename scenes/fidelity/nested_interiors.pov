// povml fidelity scene: nested_interiors
// Rule: the interior list decides the ior ratio: entering from atmosphere atm/I; entering while
//       inside others last/I; leaving the innermost I/(next or atm); leaving an overlap region
//       ior 1 (straight) (docs/povray-rules.md §6.2, §6.4).
// Left: a glass ball (ior 1.5) containing an air bubble (ior 1.0) off-centre.
// Middle: glass (ior 1.5) filled with a water ball (ior 1.33), not concentric.
// Right: two overlapping glass balls with different ior (1.3, 1.7).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1.5, -6> look_at <0, 1.0, 0> right x*image_width/image_height }
background { rgb <0.4, 0.5, 0.7> }
light_source { <-3, 6, -5>, rgb 1 }
#declare Clear = pigment { rgbf <1, 1, 1, 0.95> };
#declare GlassFin = finish { ambient 0 diffuse 0 phong 0.6 phong_size 100 };
sphere { <-2.2, 1.0, 0>, 0.9 pigment { Clear } finish { GlassFin } interior { ior 1.5 } }
sphere { <-2.0, 1.2, -0.2>, 0.4 pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } interior { ior 1.0 } }
sphere { < 0.0, 1.0, 0>, 0.9 pigment { Clear } finish { GlassFin } interior { ior 1.5 } }
sphere { < 0.1, 0.9, 0.1>, 0.65 pigment { rgbf <0.7, 0.85, 1, 0.9> } finish { ambient 0 diffuse 0 } interior { ior 1.33 } }
sphere { < 1.9, 1.0, 0>, 0.7 pigment { rgbf <1, 0.9, 0.9, 0.95> } finish { GlassFin } interior { ior 1.3 } }
sphere { < 2.6, 1.1, 0.3>, 0.6 pigment { rgbf <0.9, 0.9, 1, 0.95> } finish { GlassFin } interior { ior 1.7 } }
sphere { <-1.0, 0.4, 3.0>, 0.5 pigment { rgb <0.9, 0.3, 0.1> } }
sphere { < 1.2, 0.5, 3.0>, 0.5 pigment { rgb <0.2, 0.7, 0.2> } }
plane { y, -0.2 pigment { rgb <0.8, 0.8, 0.8> } }
plane { z, 6 pigment { rgb <0.3, 0.3, 0.6> } }
