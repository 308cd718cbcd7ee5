// povml fidelity scene: torus_glass
// Rule: a torus is a closed solid (Inside: P.y² + (√(P.x²+P.z²) − R)² ≤ r², docs/povray-rules.md
//       §15.5): a ray refracts into the tube and out again with the interior list (§6.2, §6.4),
//       crossing up to four surfaces; shadows through it are filtered (§4).
// A glass torus standing up and a flatter transparent one, in front of coloured objects.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, -5.5> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.25, 0.35, 0.55> }
light_source { <-3, 6, -5>, rgb 1 }
torus { 0.8, 0.3 rotate x*90 rotate y*20 translate <-0.6, 1.1, 0>
        pigment { rgbf <0.95, 0.98, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.8 reflection 0.05 }
        interior { ior 1.5 fade_distance 2 fade_power 1 } }
torus { 0.6, 0.25 scale <1, 0.7, 1> translate <1.1, 0.18, -0.9>
        pigment { rgbt <0.9, 1, 0.9, 0.8> } finish { ambient 0 diffuse 0.1 } interior { ior 1.33 } }
box { <-2, 0, 1.5>, <-1, 2, 2> pigment { rgb <0.9, 0.2, 0.2> } }
box { <-0.5, 0, 1.5>, <0.5, 2, 2> pigment { rgb <0.2, 0.9, 0.2> } }
box { <1, 0, 1.5>, <2, 2, 2> pigment { rgb <0.2, 0.2, 0.9> } }
sphere { <0.3, 0.4, 0.8>, 0.4 pigment { rgb <1, 0.9, 0.3> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
