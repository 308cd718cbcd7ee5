// povml fidelity scene: image_bump_sphere
// Rule: bump_map map_type 1 on a sphere, the amount after the block
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -3> look_at 0 angle 50 }
light_source { <-3, 5, -6> rgb 1 }
sphere { 0, 1 pigment { rgb <0.9,0.7,0.5> } normal { bump_map { png "../images/grey.png" map_type 1 interpolate 2 } 1.5 } rotate y*30 }
