// povml fidelity scene: camera_inside_glass
// Rule: a camera inside a sphere starts with that sphere's interior in its list, so its first
//       hit is an exit from glass (ratio 1.5/1); rays meeting the surface beyond the critical
//       angle are totally internally reflected (docs/povray-rules.md §6.4, §6.2, §2.2 Inside).
// The camera sits off-centre inside a big glass ball (ior 1.5, radius 3) and looks out at
// coloured balls. The floor (y = -0.5) cuts through the glass ball. Near the right edge the rays
// meet the surface beyond the critical angle; a ray trapped by TIR in a sphere keeps being
// reflected until max_trace_level cuts it off, so part of that region is BLACK (§7).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <1.7, 1.2, -1.6> look_at <0.5, 1.0, 6> right x*image_width/image_height }
background { rgb <0.4, 0.55, 0.8> }
light_source { <-3, 9, -6>, rgb 1 }
sphere { <0, 1, 0>, 3 pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { ambient 0 diffuse 0 } interior { ior 1.5 } }
sphere { <-1.5, 0.5, 6>, 0.8 pigment { rgb <0.9, 0.25, 0.2> } }
sphere { < 1.5, 1.2, 7>, 1.0 pigment { rgb <0.2, 0.7, 0.3> } }
sphere { < 4.5, 0.5, 2>, 0.8 pigment { rgb <0.9, 0.8, 0.2> } }
plane { y, -0.5 pigment { rgb <0.6, 0.6, 0.65> } }
