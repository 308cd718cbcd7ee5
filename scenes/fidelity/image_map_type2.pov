// povml fidelity scene: image_map_type2
// Rule: map_type 2: a cylindrical image_map on a cylinder
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -3> look_at <0,0.5,0> angle 50 }
light_source { <-3, 5, -6> rgb 1 }
cylinder { 0, y, 1 pigment { image_map { png "../images/rgb8.png" map_type 2 } } rotate y*20 }
