// povml fidelity scene: uv_torus
// Rule: Torus::CalcUV in torus space: u = 1 − (atan2(z, x) + π)/2π, v = (atan2(y, ρ − R) + π)/2π.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
torus { 1, 0.4
  pigment { uv_mapping checker rgb <1, 0.3, 0.1> rgb <0.1, 0.3, 1> scale <1/24, 1/8, 1> }
  finish { ambient 0.15 diffuse 0.8 }
  rotate <-40, 20, 0> translate <-0.2, 0.2, 0> }
plane { y, -1 pigment { rgb 0.6 } }
