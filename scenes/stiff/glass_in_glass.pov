// povml stiff scene: glass_in_glass
// Stresses: nested and overlapping interiors (§6.2, §6.4). Left: a glass ball (ior 1.5) holding
// a smaller ball of the same ior (crossing it is an ior-1 crossing: continued, no level used)
// and an air bubble (ior 1.0 inside 1.5: the ratio 1.5 gives total internal reflection, so the
// bubble shines silvery at its rim). Middle: a glass ball holding a water drop (ior 1.33 inside
// 1.5, a weak diverging lens) that itself holds a tiny dense core (ior 2.4). Right: two glass
// balls of different ior that overlap; POV-Ray treats leaving the first-entered one while still
// inside the other as ior 1 (§6.2 "leaving an overlap region"), which is physically wrong but
// is what a correct (POV-Ray-equal) image shows: the lens shape of the overlap refracts as if
// it were air at one of its faces.
// A correct image: three glass groups on a pale floor before a green and a red wall, each inner
// body visible as its own lens; the bubble bright at its edge; no black speckles where
// nested surfaces meet.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 2.2, -6.5> look_at <0, 0.8, 0> right x*image_width/image_height angle 60 }
background { rgb <0.35, 0.55, 0.9> }
light_source { <-3, 9, -8>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
plane { z, 3 pigment { rgb <0.3, 0.6, 0.35> } }
plane { x, -4.5 pigment { rgb <0.8, 0.35, 0.3> } }
#declare Clear = texture { pigment { rgbf <1, 1, 1, 0.97> } finish { ambient 0 diffuse 0 phong 0.6 reflection { 0, 1 fresnel } } }
// left
sphere { <-2.6, 1.1, 0>, 1.0 texture { Clear } interior { ior 1.5 } }
sphere { <-2.9, 1.3, -0.2>, 0.4 texture { Clear } pigment { rgbf <1, 0.7, 0.7, 0.97> } interior { ior 1.5 } }
sphere { <-2.2, 0.8, -0.3>, 0.35 texture { Clear } interior { ior 1.0 } }
// middle
sphere { <0, 1.1, 0>, 1.0 texture { Clear } interior { ior 1.5 } }
sphere { <0.1, 1.0, -0.1>, 0.6 texture { Clear } pigment { rgbf <0.7, 0.85, 1, 0.97> } interior { ior 1.33 } }
sphere { <0.15, 0.95, -0.2>, 0.2 texture { Clear } interior { ior 2.4 } }
// right
sphere { <2.3, 1.0, 0>, 0.9 texture { Clear } interior { ior 1.5 } }
sphere { <3.1, 1.0, 0.3>, 0.8 texture { Clear } pigment { rgbf <1, 1, 0.7, 0.97> } interior { ior 1.7 } }
