// povml stiff scene: light_on_surface
// Stresses: lights lying exactly on surfaces. One light is on the floor plane (y = 0), one at the
// top point of a sphere, one on a horizontal triangle. A floor point sees the floor light at
// N·L = 0 up to rounding and must stay unlit by it (§3.3: lights with N·L < 1e-10 are skipped);
// every point of the sphere sees the light on it from below its tangent plane (a chord leaves at
// N·L < 0), so the sphere is unlit by it; and a shadow ray towards a light on a surface meets
// that surface within 1e-3 of the light, where hits do not count (§4), so the surface does not
// block its own light. Objects on the floor are lit by the floor light from the horizon, with
// long shadows along the floor.
// What POV-Ray gets wrong here, and povml reproduces: the triangle does not shadow the light
// lying on it, so the light shines through it and lights the floor underneath in green.
// A correct image: a floor lit by the high light, orange-tinted near the floor light and green
// under the triangle; the small balls lit orange on the side facing the floor light, with long
// shadows; the big sphere lit only by the high light and the floor light; the ball above the
// triangle lit green from below; no NaN and no speckles where a hit point comes close to a light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> right x*image_width/image_height angle 60 }
background { rgb <0.1, 0.12, 0.18> }
light_source { <3, 8, -6>, rgb 0.5 }
light_source { <0, 0, 0>, rgb <1, 0.6, 0.3> }
light_source { <2.5, 2, 1>, rgb <0.3, 0.6, 1> }
light_source { <-2.4, 0.8, 0.5>, rgb <0.6, 1, 0.5> }
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
sphere { <-1.2, 0.4, 0.6>, 0.4 pigment { rgb 0.9 } }
sphere { < 1.0, 0.3, -0.8>, 0.3 pigment { rgb 0.9 } }
sphere { <2.5, 1.2, 1>, 0.8 pigment { rgb <0.8, 0.8, 0.9> } finish { phong 0.5 } }
triangle { <-3.2, 0.8, -0.5>, <-1.6, 0.8, 0.5>, <-3.0, 0.8, 1.5> pigment { rgb <0.9, 0.5, 0.4> } }
sphere { <-2.4, 1.6, 0.5>, 0.35 pigment { rgb 0.9 } }
