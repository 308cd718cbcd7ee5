// povml stiff scene: camera_in_sphere
// Stresses: a camera inside closed objects. The camera starts inside a large opaque sphere (the
// room, seen from inside: its normal is flipped towards the camera, §3.1) and inside a glass
// ball of radius 0.6, 0.35 off its centre: every camera ray starts with both in its interior list
// (§6.4), so its first hit on the glass is an exit (ratio 1.5 to 1). Rays meeting the glass at
// more than 41.8 degrees are totally reflected, and in a sphere every further reflection repeats
// that angle: they stay trapped until max_trace_level 12 cuts them off. A transparent ior-1 ball
// nearby, not containing the camera, is entered at its first hit.
// A correct image: on the left, through the glass's escape window, the room's wall and floor and
// the red ball, strongly distorted; on the right, where the rays are trapped, black, fringed with
// the thin bright arcs of rays that escape after a few reflections; no NaN.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0.35, 1.2, -0.2> look_at <0.2, 1.0, 3> right x*image_width/image_height angle 75 }
light_source { <0, 4, 0>, rgb 1 }
sphere { <0, 1, 0>, 6 pigment { rgb <0.7, 0.75, 0.85> } finish { ambient 0.15 diffuse 0.6 } }
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
sphere { <0, 1.2, 0>, 0.6
  pigment { rgbf <0.95, 1, 0.97, 0.95> } finish { ambient 0 diffuse 0 phong 0.6 reflection { 0, 1 fresnel } }
  interior { ior 1.5 } }
sphere { <0.9, 1.3, 0.6>, 0.5 pigment { rgbt <1, 1, 0.8, 0.7> } finish { ambient 0 diffuse 0.2 } }
sphere { <-1.2, 0.7, 3>, 0.7 pigment { rgb <0.9, 0.2, 0.15> } finish { phong 0.5 } }
sphere { <1.5, 0.5, 3.5>, 0.5 pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
