// povml stiff scene: tiny_far
// Stresses: small objects far from the origin. Balls of radius S (default 1e-3) rest on a ground
// sphere of radius 1e6 whose top is at y = Y (default 1e6), seen from 2·S above the ground; both
// can be set on the command line (Declare=Y=1e4 Declare=S=0.01). POV-Ray keeps bounding boxes and
// the ray's origin in single precision when it searches its bounding tree: at 1e6 a step of
// single precision is 0.0625, so a ball of 1e-3 has a box of no thickness, and the camera's rays
// miss it, while the shadow rays that leave the ground below it still meet it.
// What POV-Ray gets wrong here, and povml reproduces in its default mode: at Y = 1e6 the balls are
// not drawn, only their shadows; at 1e5 and below, or with S = 1, the scene looks as written.
// The ground is infinite to POV-Ray (a box of volume above 2e10) and outside its tree.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Y) #declare Y = 1e6; #end
#ifndef (S) #declare S = 1e-3; #end
camera { location <S, Y + 2 * S, -9 * S> look_at <0, Y + 0.8 * S, 0> right x*image_width/image_height angle 60 }
background { rgb <0.45, 0.6, 0.85> }
light_source { <-20 * S, Y + 30 * S, -10 * S>, rgb 1 }
sphere { <0, Y - 1e6, 0>, 1e6 pigment { rgb <0.85, 0.8, 0.7> } finish { phong 0.3 } }
sphere { <-2.2 * S, Y + S, 0.5 * S>, S pigment { rgb <0.9, 0.2, 0.15> } finish { phong 0.6 } }
sphere { <0, Y + S, 0>, S pigment { rgb <0.8, 0.85, 0.9> } finish { ambient 0.05 diffuse 0.2 reflection 0.7 } }
sphere { <2 * S, Y + S, 0>, S pigment { rgb <0.2, 0.7, 0.3> } finish { phong 0.6 } }
