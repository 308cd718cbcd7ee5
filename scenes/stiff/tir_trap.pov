// povml stiff scene: tir_trap
// Stresses: total internal reflection near the recursion limit. The camera is inside a glass
// ball of ior 3.0 (it starts in the ball's interior, §6.4), off its centre. A ray leaving the
// ball meets the surface at an angle that, in a sphere, every internal reflection repeats: rays
// past the 19.5-degree critical angle are trapped and reflect forever. With adc_bailout 0 (a TIR
// ray keeps its weight, §6.2) each such ray recurses through refraction calls (not reflection
// ones) until max_trace_level cuts it off and it returns black. The level is Trap_level: 200
// here, 256 when tir_trap_256.pov includes this file.
// What POV-Ray gets wrong: POV-Ray 3.7.0.10 crashes (SIGSEGV) on this scene from
// max_trace_level 218 on: each nested refraction takes about 19 KB of its render thread's fixed
// 4 MB stack (a larger ulimit -s does not help). Level 200 is the reference; povml must also run
// the 256 version (tir_trap_256.pov) without a stack overflow.
// A correct image: a disc (the escape cone, where rays leave the ball) showing the floor, the
// wall and the balls outside, shrunk and distorted; outside it the trapped rays are a smooth grey
// made of the highlights and faint glass colour they pick up at every bounce; no NaN.
#version 3.7;
#ifndef (Trap_level) #declare Trap_level = 200; #end
global_settings { assumed_gamma 1.0 max_trace_level Trap_level adc_bailout 0 }
camera { location <0.25, 1.3, 0.45> look_at <0.5, 1.0, 4> right x*image_width/image_height angle 80 }
background { rgb <0.35, 0.55, 0.9> }
light_source { <-3, 9, -6>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
plane { z, 6 pigment { rgb <0.9, 0.5, 0.2> } }
sphere { <1.8, 0.6, 4>, 0.6 pigment { rgb <0.2, 0.7, 0.3> } }
sphere { <-1.2, 0.5, 3.5>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } }
sphere { <0, 1.2, 0>, 1.1
  pigment { rgbf <0.97, 1, 0.98, 0.98> } finish { ambient 0.01 diffuse 0 phong 0.5 }
  interior { ior 3.0 } }
