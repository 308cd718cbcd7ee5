// povml fidelity scene: uv_sphere
// Rule: pigment { uv_mapping … } on a sphere evaluates the pattern at Sphere::UVCoord's (u, v, 0):
//       u = θ/2π about the y axis from +x towards +z, v = 0.5 + asin(y)/π (spheres.cpp).
//       Left: a checker 16 × 8 cells; right: a gradient x (u) ramp with a colour map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
sphere { <-1.2, 0, 0>, 1
  pigment { uv_mapping checker rgb <1, 0.3, 0.1> rgb <0.1, 0.3, 1> scale <1/16, 1/8, 1> }
  finish { ambient 0.15 diffuse 0.8 } }
sphere { <1.2, 0, 0>, 1
  pigment { uv_mapping gradient x color_map { [0 rgb <1, 1, 0>] [0.5 rgb <0, 0.6, 0.3>] [1 rgb <0.8, 0, 0.6>] } }
  finish { ambient 0.15 diffuse 0.8 } }
plane { y, -1 pigment { rgb 0.6 } }
