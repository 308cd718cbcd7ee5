// povml stiff scene: camera_near_plane
// Stresses: the minimum hit depth seen by a camera. The camera is 5e-5 below an opaque ceiling
// plane and looks up at it. Every ray ignores hits closer than 1e-4 (MIN_ISECT_DEPTH, §2.1), so
// the rays that meet the ceiling less than 1e-4 away, those within 60 degrees of the vertical,
// pass straight through it and see what is above; the others see the ceiling.
// What POV-Ray gets wrong here, and povml reproduces: a hole in the ceiling, a disc of the sky
// and of the ball above the ceiling, whose edge is the cone of rays meeting the plane exactly
// 1e-4 away. The ceiling around it is lit by a light below it.
// A correct image: a round hole with a sharp edge in a pale ceiling, the blue sky through it and
// the dark underside of the yellow ball (its light is above it); no NaN.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1 - 5e-5, 0> look_at <0, 2, 0> sky <0, 0, 1> right x*image_width/image_height angle 150 }
background { rgb <0.35, 0.55, 0.9> }
light_source { <0.5, 0.2, 0.3>, rgb 1 }
light_source { <0, 8, -2>, rgb 1 }
plane { y, 1 pigment { rgb <0.9, 0.85, 0.75> } }
plane { y, 0 pigment { rgb <0.5, 0.5, 0.5> } }
sphere { <0.3, 2.5, 0.4>, 0.5 pigment { rgb <0.95, 0.8, 0.2> } }
