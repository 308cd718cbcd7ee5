// povml fidelity scene: image_lit
// Rule: an image_map on a lit, rotated box, with phong
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1, 2, -3> look_at 0.5 angle 50 }
light_source { <-3, 5, -6> rgb 1 }
box { 0, 1 pigment { image_map { png "../images/rgb8.png" } } finish { phong 0.5 } rotate y*20 }
