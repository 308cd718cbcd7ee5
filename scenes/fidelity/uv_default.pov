// povml fidelity scene: uv_default
// Rule: shapes without a UVCoord of their own (plane, cylinder, cone, disc, triangle, polygon)
//       use ObjectBase::UVCoord: the world point's x and y as they are, whatever their transform.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, -1 pigment { uv_mapping checker rgb 1 rgb 0.3 scale 0.5 } }
cylinder { <-1.8, -1, 0>, <-1.8, 1, 0>, 0.5
  pigment { uv_mapping checker rgb <1, 0.3, 0.1> rgb <0.1, 0.3, 1> scale 0.2 } rotate y*30 }
cone { <0, -1, 0.5>, 0.8, <0, 0.8, 0.5>, 0.1
  pigment { uv_mapping gradient x color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 0.4, 0.8>] } scale 0.5 } }
disc { <1.8, 0, 0>, <-0.3, 0.2, -1>, 0.7
  pigment { uv_mapping checker rgb <1, 1, 0.2> rgb <0.2, 0.6, 0.2> scale 0.25 } }
