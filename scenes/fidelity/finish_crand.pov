// povml fidelity scene: finish_crand
// Rule: crand takes a random amount, crand times POV-Ray's POV_rand, off each light's diffuse
//       intensity; the random stream is one per render thread, never reset, so the image is
//       POV-Ray's one-thread image (+WT1), and povml renders such a scene in one worker.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
light_source { <3, 4, -5>, rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } finish { crand 0.3 } }
sphere { <-1.1, 1, 0.5>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { crand 0.15 phong 0.5 reflection 0.2 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> texture { pigment { rgb <0.3, 0.6, 0.9> } finish { crand 0.5 } } texture { pigment { checker rgbt <1, 1, 1, 0.5>, rgbt 1 scale 0.3 } finish { crand 0.2 } } }
