// povml stiff scene: light_in_glass
// Stresses: a point light inside transparent objects. The left light sits inside a hollow glass
// ball (ior 1.5, filtering, with fade_distance and fade_power 2) with a small opaque ball next to
// it; the right light is inside a closed opaque ball and lights only that ball's inside. Shadow
// rays are not refracted (§4): they leave the glass ball in a straight line, filtered once by
// its colour at the crossing. The glass interior's fade would apply to the shadow ray's segment
// inside the glass, but a shadow ray that starts outside enters the glass list only at its first
// crossing and then ends at the light, so it is never faded (§4: the fade applies only when the
// ray's interior list already holds the object) — what POV-Ray gets wrong, physically.
// A correct image: the floor lit through the glass in its pale blue tint, with the dark shadow
// of the small inner ball on it; the glass ball showing the red inner ball and the light's
// glow; the yellow ball on the right lit only from outside by the left light (its own light,
// at its centre, reaches nothing) and casting its shadow to the right.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2.5, -6> look_at <0, 0.9, 0> right x*image_width/image_height angle 60 }
background { rgb <0.1, 0.12, 0.18> }
light_source { <-1.2, 1.3, 0>, rgb <1, 0.95, 0.85> }
light_source { <2.0, 1.0, 0.5>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
plane { z, 4 pigment { rgb <0.6, 0.65, 0.7> } }
sphere { <-1.2, 1.3, 0>, 1.0
  pigment { rgbf <0.7, 0.9, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.9 phong_size 60 reflection { 0, 1 fresnel } }
  interior { ior 1.5 fade_distance 0.8 fade_power 2 fade_color <0.5, 0.8, 1> } }
sphere { <-1.2, 0.85, -0.2>, 0.25 pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <2.0, 1.0, 0.5>, 0.7 pigment { rgb <0.9, 0.9, 0.5> } finish { ambient 0.1 } }
