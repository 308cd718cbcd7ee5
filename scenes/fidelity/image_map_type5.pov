// povml fidelity scene: image_map_type5
// Rule: map_type 5: a torus image_map
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -3> look_at 0 angle 50 }
light_source { <-3, 5, -6> rgb 1 }
torus { 1, 0.4 pigment { image_map { png "../images/rgb8.png" map_type 5 } } rotate y*20 }
