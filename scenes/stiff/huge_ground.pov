// povml stiff scene: huge_ground
// Stresses: a range of scales of 1e9 in one scene. The ground is a sphere of radius 1e6 whose top
// is at y = 0; on it stand balls of radius 1e-3 (and one of 2e-4), seen from 1 cm away. The ray-
// sphere test for the ground subtracts squares of about 1e12 (§2.2), so its depth carries an
// absolute error near 1e-10; the balls are only ten times POV-Ray's shadow tolerance (1e-3, §4)
// and the smallest one is close to the 1e-4 minimum hit depth (§2.1).
// What POV-Ray gets wrong here, and povml reproduces in its default mode: shadow-ray hits closer
// than 1e-3 do not count, so the shadow of each ball is missing where it is thinner than 1e-3
// (a lit gap around each contact point, and the 2e-4 ball casts no shadow at all), and the
// mirror ball does not reflect its touching neighbour within 1e-4 of the contact.
// A correct image otherwise: a flat-looking pale ground without acne, four lit balls with
// shadows towards the camera-right, the mirror ball reflecting the others and the sky.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.001, 0.0035, -0.009> look_at <0, 0.0008, 0> right x*image_width/image_height angle 60 }
background { rgb <0.45, 0.6, 0.85> }
light_source { <-0.02, 0.03, -0.01>, rgb 1 }
sphere { <0, -1e6, 0>, 1e6 pigment { rgb <0.85, 0.8, 0.7> } finish { phong 0.3 } }
sphere { <-0.0022, 0.001, 0.0005>, 0.001 pigment { rgb <0.9, 0.2, 0.15> } finish { phong 0.6 } }
sphere { < 0, 0.001, 0>, 0.001 pigment { rgb <0.8, 0.85, 0.9> } finish { ambient 0.05 diffuse 0.2 reflection 0.7 } }
sphere { < 0.002, 0.001, 0>, 0.001 pigment { rgb <0.2, 0.7, 0.3> } finish { phong 0.6 } }
sphere { < 0.0016, 0.0002, -0.0024>, 0.0002 pigment { rgb <0.95, 0.8, 0.2> } }
