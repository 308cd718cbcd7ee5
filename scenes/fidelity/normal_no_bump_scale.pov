// povml fidelity scene: normal_no_bump_scale
// Rule: a scaled normal keeps its bend: the normal is made unit in the normal's space and back
//       (Warp_Normal, UnWarp_Normal); with no_bump_scale it is not, so the bend shrinks with the
//       scale, and the tracer makes the result unit (trace.cpp, Vector3d::normalize). Floor:
//       scale 0.25 without, then with no_bump_scale, then no_bump_scale at scale 0.6; the
//       sphere with no_bump_scale on a non-uniform scale; the box passes no_bump_scale down to
//       the normals of its normal_map (Post_Tnormal).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
#declare F = finish { phong 0.4 }
box { <-4, -1, -2>, <-1.5, 0, 4> pigment { rgb 0.8 } normal { gradient z 0.8 triangle_wave scale 0.25 } finish { F } }
box { <-1.5, -1, -2>, <1, 0, 4> pigment { rgb 0.8 } normal { gradient z 0.8 triangle_wave scale 0.25 no_bump_scale } finish { F } }
box { <1, -1, -2>, <4, 0, 4> pigment { rgb 0.8 } normal { gradient z 0.8 triangle_wave no_bump_scale scale 0.6 } finish { F } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { quilted 1 scale <0.2, 0.5, 0.3> no_bump_scale } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { gradient x normal_map { [0 gradient y 1 scale 0.1] [1 quilted 0.6 scale 0.2] } scale 0.7 no_bump_scale }
      finish { specular 0.6 roughness 0.02 } }
