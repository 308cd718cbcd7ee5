// povml fidelity scene: uv_box
// Rule: Box::UVCoord maps each side onto a cube map's cross (u in quarters, v in thirds), the
//       point made relative to the box first; a rotated box in its own space (boxes.cpp).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
box { <-1, -1, -1>, <1, 1, 1>
  pigment { uv_mapping checker rgb <1, 0.3, 0.1> rgb <0.1, 0.3, 1> scale <1/16, 1/12, 1> }
  finish { ambient 0.15 diffuse 0.8 }
  rotate <20, 35, 0> translate <-1.3, 0, 0> }
box { <0, -0.5, 0>, <1.5, 1, 1>
  pigment { uv_mapping gradient y color_map { [0 rgb <1, 1, 0>] [0.5 rgb <0, 0.6, 0.3>] [1 rgb <0.8, 0, 0.6>] } }
  finish { ambient 0.15 diffuse 0.8 }
  translate <0.6, -0.3, -0.5> }
plane { y, -1 pigment { rgb 0.6 } }
