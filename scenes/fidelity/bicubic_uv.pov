// uv_mapping on bicubic patches: the texture coordinates of a crossing are its patch parameters
// (u, v) mapped into the quadrilateral of the patch's uv_vectors (BicubicPatch::UVCoord and
// Compute_Texture_UV); by default (0,0), (1,0), (1,1), (0,1), which gives (v, u).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -6> look_at <0, 0, 0.3> angle 55 }
light_source { <3, 10, -6> rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
#declare Pts = array[16] {
  <0,0,0>, <1,0,0>, <2,0,0>, <3,0,0>, <0,0,1>, <1,1.5,1>, <2,1.5,1>, <3,0,1>,
  <0,0,2>, <1,1.5,2>, <2,1.5,2>, <3,0,2>, <0,0,3>, <1,0,3>, <2,0,3>, <3,0,3> }
#macro Patch(Type, Steps)
  Pts[0], Pts[1], Pts[2], Pts[3], Pts[4], Pts[5], Pts[6], Pts[7],
  Pts[8], Pts[9], Pts[10], Pts[11], Pts[12], Pts[13], Pts[14], Pts[15]
#end
// the default uv_vectors, type 1
bicubic_patch { type 1 flatness 0.01 u_steps 3 v_steps 3 Patch(1, 3)
  uv_mapping pigment { checker rgb 1 rgb <0.8, 0.1, 0.1> scale 0.125 } translate <-3.3, 0, -1> }
// type 0, a gradient along u
bicubic_patch { type 0 flatness 0 u_steps 2 v_steps 3 Patch(0, 2)
  uv_mapping pigment { gradient x color_map { [0 rgb <0, 0, 1>] [1 rgb <1, 1, 0>] } } translate <0.3, 0, -1> }
// uv_vectors: a rotated and stretched quadrilateral; an image-like pattern through it
bicubic_patch { type 1 flatness 0.02 u_steps 3 v_steps 3 uv_vectors <0.1, 0.2>, <2, 0.3>, <1.8, 1.9>, <0.3, 2.1>
  Patch(1, 3)
  uv_mapping pigment { checker rgb <0.1, 0.6, 0.1> rgb 1 scale 0.25 } translate <-1.5, 0, 2> }
