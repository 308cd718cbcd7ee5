// povml fidelity scene: image_map_type1
// Rule: map_type 1: a spherical image_map on a lit sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -3> look_at 0 angle 50 }
light_source { <-3, 5, -6> rgb 1 }
sphere { 0, 1 pigment { image_map { png "../images/rgb8.png" map_type 1 } } rotate y*30 }
