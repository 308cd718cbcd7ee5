// povml fidelity scene: torus_inverse
// Rule: inverse negates a torus's Inside test (docs/povray-rules.md §15.5). The camera stands in the
//       hole of a large inverse glass torus: within its bounding box and outside the tube, so it
//       counts as inside the object and camera rays start in its interior (§6.4: POV-Ray asks
//       Inside_BBox before Inside); where they cross the tube's wall they LEAVE the interior, so
//       the ior ratio is 1.5 where a plain torus gives 1/1.5 (§6.2). A small plain glass torus in
//       front, and a second inverse torus whose box does not hold the camera (rendered as a
//       plain one), for comparison.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 0.4, 0> look_at <0, 0, 5> right x*image_width/image_height }
background { rgb <0.25, 0.35, 0.55> }
light_source { <-3, 6, -2>, rgb 1 }
torus { 4, 1 inverse
        pigment { rgbf <0.95, 0.98, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.8 }
        interior { ior 1.5 } }
torus { 0.5, 0.2 rotate x*80 translate <0.9, 0.2, 2.2>
        pigment { rgbf <0.95, 0.98, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.8 }
        interior { ior 1.5 } }
torus { 0.5, 0.2 inverse rotate x*80 translate <-0.9, 0.2, 2.2>
        pigment { rgbf <0.95, 0.98, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.8 }
        interior { ior 1.5 } }
box { <-4, -2, 6>, <-1, 2, 6.5> pigment { rgb <0.9, 0.2, 0.2> } }
box { <-1, -2, 6>, <1, 2, 6.5> pigment { rgb <0.2, 0.9, 0.2> } }
box { <1, -2, 6>, <4, 2, 6.5> pigment { rgb <0.2, 0.2, 0.9> } }
sphere { <0, 1.8, 5.5>, 0.5 pigment { rgb <1, 0.9, 0.3> } }
plane { y, -1.2 pigment { rgb <0.85, 0.85, 0.8> } }
