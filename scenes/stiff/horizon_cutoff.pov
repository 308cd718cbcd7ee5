// povml stiff scene: horizon_cutoff
// Stresses: the largest hit depth. Every shape rejects hits beyond 1e7 (MAX_DISTANCE, §2.1), so
// an infinite plane seen at a grazing angle ends before its horizon. The camera hovers 5e4 above
// a floor plane and looks at the horizon through a narrow (10 degree) lens: rays less than 5e-3
// radians below the horizontal would meet the floor more than 1e7 away and see the background.
// A mirror ball of radius 2e4 stands on the floor 5e5 away; its reflected rays start there.
// What POV-Ray gets wrong here, and povml reproduces: the floor stops 5e-3 radians short of the
// true horizon, a band of background about four pixel rows high.
// A correct image: a dark floor under a pale sky, the floor's far edge on the image's centre row
// (the camera looks 5e-3 radians down) though the true horizon is about four rows higher; the
// mirror ball at the lower left reflecting floor and sky; no NaN.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5e4, 0> look_at <0, 5e4 - 2500, 5e5> right x*image_width/image_height angle 10 }
background { rgb <0.6, 0.75, 0.95> }
light_source { <-3e6, 2e6, -1e6>, rgb 1 }
plane { y, 0 pigment { rgb <0.25, 0.3, 0.2> } }
sphere { <-3e4, 2e4, 5e5>, 2e4 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.2 reflection 0.7 } }
