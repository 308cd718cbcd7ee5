// Rule: without a background statement, missed rays are opaque black in a legacy scene too
// (POV-Ray sets the background to black with transmit 0 when it writes no alpha channel): so the
// edges of an object against them are antialiased only where their colours differ enough.
// A #version 3.6 scene with assumed_gamma, antialiased (portfolio/allpatterns.pov's box).
#version 3.6;
global_settings { assumed_gamma 1.0 }
box { -1.5,1.5 translate<0,0,1.5> texture{ pigment { agate colour_map {[0, rgb 0][1, rgb 1]} } } translate<0,0,-1.5> rotate <0,-35,0> rotate <-25,0,0> }
camera { right x*image_width/image_height location <0,0,-8> look_at <0,-0.25,0> angle 35 }
light_source{<500,10,-500> rgb 1}
light_source{<-500,500,-500> rgb <0.6,0.6,0.8>}
