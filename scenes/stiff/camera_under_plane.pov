// povml stiff scene: camera_under_plane
// Stresses: a camera on the inside of planes. The camera is below three planes, so inside each
// (the side opposite the normal, §2.3): an opaque ceiling y = 3, a plane with normal -y at
// y = -0.5 (its inside is everything above it; its underside is the floor), and, declared last, a
// filtering glass plane y = 1.2 with ior 1.2. Camera rays start with all three interiors, the
// last declared last (§6.4); every object has an interior, opaque ones included. The first hit on
// the glass plane is then an exit from the innermost interior (ratio 1.2 to 1), and beyond
// 56.4 degrees from the vertical it is totally reflected. Had the glass plane been declared
// before the other two, that exit would leave an interior that is not the last one, which POV-Ray
// treats as leaving an overlap with ior 1 (§6.2): no bending and no total reflection at all.
// The light is between the glass and the ceiling, so shadow rays from the floor cross the glass
// once, filtered (§4).
// A correct image: the floor with a red and a blue ball and their shadows; above, Snell's window:
// a disc of the ceiling lit by the light, seen through the glass; around it the glass plane's
// total reflection of the floor and the balls, upside down; no NaN.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 0.6, -3> look_at <0, 1.6, 0> right x*image_width/image_height angle 80 }
background { rgb <0.35, 0.55, 0.9> }
light_source { <1, 2.5, -1>, rgb 1 }
plane { y, 3 pigment { rgb <0.9, 0.85, 0.6> } }
plane { -y, 0.5 pigment { rgb <0.7, 0.8, 0.7> } }
plane { y, 1.2 pigment { rgbf <0.85, 0.95, 1, 0.9> } finish { ambient 0 diffuse 0.05 } interior { ior 1.2 } }
sphere { <-0.8, 0.0, 1>, 0.5 pigment { rgb <0.9, 0.2, 0.15> } }
sphere { < 1.0, -0.1, 2.5>, 0.4 pigment { rgb <0.2, 0.3, 0.9> } }
