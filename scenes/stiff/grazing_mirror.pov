// povml stiff scene: grazing_mirror
// Stresses: grazing incidence on a reflective plane. The camera is 0.02 above a Fresnel mirror
// (reflection { 0, 1 fresnel } with ior 1.5) and looks along it, so near the horizon the camera
// rays meet the plane at cosines of 1e-3 and less: the Fresnel term tends to 1 there (§5.2), the
// reflected ray starts exactly on the plane and must not hit it again (only the 1e-6 / 1e-4
// depth limits keep it off, §2.1), and the diffuse and phong terms see N·L near 0.
// A correct image: a dark glassy floor that brightens smoothly into a near-perfect mirror
// towards the horizon, reflecting the red and yellow balls and the sky; no speckles (self-hits)
// on the floor; the reflections of the balls meet the balls at their contact points.
// An antialiased variant (+A0.3) checks the supersampled horizon and ball edges.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 0.02, -4> look_at <0, 0.6, 10> right x*image_width/image_height angle 50 }
background { rgb <0.35, 0.55, 0.9> }
light_source { <-30, 0.5, 40>, rgb 1 }
plane { y, 0
  pigment { rgb <0.05, 0.06, 0.08> }
  finish { ambient 0.05 diffuse 0.3 phong 0.8 phong_size 200 reflection { 0, 1 fresnel } }
  interior { ior 1.5 }
}
sphere { <-1.2, 0.6, 3>, 0.6 pigment { rgb <0.9, 0.2, 0.15> } finish { phong 0.5 } }
sphere { < 1.5, 1.0, 12>, 1.0 pigment { rgb <0.95, 0.8, 0.2> } finish { phong 0.5 } }
sphere { < 0.2, 0.05, 0.5>, 0.05 pigment { rgb <0.2, 0.7, 0.3> } }
