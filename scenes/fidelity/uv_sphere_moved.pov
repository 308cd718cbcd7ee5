// povml fidelity scene: uv_sphere_moved
// Rule: a sphere takes its UV coordinates in the frame of every modifier it got (UV_Trans, kept
//       by Translate_Object and the others besides the centre they bake); a uv-mapped pigment
//       ignores the object's transforms (they go to the UV_MAP_PATTERN wrapper, never warped).
//       Left: rotated and translated; middle: scaled unevenly (an ellipsoid) after a translate;
//       right: rotated, scaled uniformly, translated, with the pigment's own scale and rotate.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
sphere { 0, 1
  pigment { uv_mapping checker rgb <1, 0.3, 0.1> rgb <0.1, 0.3, 1> scale <1/16, 1/8, 1> }
  finish { ambient 0.15 diffuse 0.8 }
  rotate <30, 40, 10> translate <-1.8, 0.1, 0.3> }
sphere { <0.2, 0, 0>, 0.8
  pigment { uv_mapping checker rgb <1, 1, 0.2> rgb <0.2, 0.6, 0.2> scale <1/12, 1/6, 1> }
  finish { ambient 0.15 diffuse 0.8 }
  translate <-0.2, 0, 0> scale <0.8, 1.3, 0.9> rotate <0, 0, 20> }
sphere { 0, 1
  pigment { uv_mapping gradient x color_map { [0 rgb <1, 0.2, 0.2>] [1 rgb <0.2, 0.2, 1>] } scale 0.25 rotate z*15 }
  finish { ambient 0.15 diffuse 0.8 }
  rotate <-20, 60, 0> scale 0.8 translate <1.7, 0, 0> }
plane { y, -1 pigment { rgb 0.6 } }
