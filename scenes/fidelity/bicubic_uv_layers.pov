// povml fidelity scene: bicubic_uv_layers
// Rule: a bicubic patch's texture coordinates are those of the crossing shaded (POV-Ray keeps
//       them in the Intersection, Iuv): each layer of a layered texture sees them, although
//       the layers below it were lit first, by 36 lights whose shadow rays cross a clear patch
//       between them and the light (and the patch itself) many times over.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -6> look_at <0, 0, 0.3> angle 45 }
#for (i, 0, 5) #for (j, 0, 5)
  light_source { <0.4*i, 10, -2 + 0.4*j> rgb 1/36 }
#end #end
background { rgb <0.2, 0.25, 0.3> }
#declare Pts = array[16] {
  <0,0,0>, <1,0,0>, <2,0,0>, <3,0,0>, <0,0,1>, <1,1.5,1>, <2,1.5,1>, <3,0,1>,
  <0,0,2>, <1,1.5,2>, <2,1.5,2>, <3,0,2>, <0,0,3>, <1,0,3>, <2,0,3>, <3,0,3> }
#macro Patch()
  Pts[0], Pts[1], Pts[2], Pts[3], Pts[4], Pts[5], Pts[6], Pts[7],
  Pts[8], Pts[9], Pts[10], Pts[11], Pts[12], Pts[13], Pts[14], Pts[15]
#end
bicubic_patch { type 1 flatness 0.01 u_steps 3 v_steps 3 Patch()
  texture { pigment { uv_mapping checker rgb 1 rgb <0.8, 0.1, 0.1> scale 0.125 } }
  texture { pigment { uv_mapping gradient x color_map { [0 rgbt <0, 0, 1, 0.5>] [1 rgbt <1, 1, 0, 0.5>] } } }
  translate <-1.5, 0, -1> }
// a clear patch between it and the lights, which the camera does not see
bicubic_patch { type 1 flatness 0.01 u_steps 3 v_steps 3 Patch()
  pigment { rgbf <1, 1, 1, 0.9> } translate <-1.5, 3, -1> no_image }
