// povml fidelity scene: normal_refraction
// Rule: the transmitted ray bends by Snell's law at the bent normal of the top layer, turned to
//       face the ray (trace.cpp, ComputeRefraction's localnormal); total internal reflection
//       reflects off the bent normal with the raw normal's fix, and the ray continues straight
//       through a surface of equal indices whatever its normal. A bumpy glass sphere, a glass
//       slab with a gradient normal, and a fresnel-reflecting bumpy glass box with ior 1.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1.8, -5.5> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.25, 0.35, 0.55> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-1.2, 0.9, 0>, 0.9 pigment { rgbf <0.95, 0.98, 1, 0.9> } normal { quilted 1.5 scale 0.3 }
         finish { ambient 0 diffuse 0.05 phong 0.8 reflection 0.05 } interior { ior 1.5 } }
box { <0.3, 0, -0.6>, <1.9, 1.6, -0.3> pigment { rgbt <0.9, 1, 0.9, 0.85> } normal { gradient x 1 triangle_wave scale 0.2 }
      finish { ambient 0 diffuse 0.1 } interior { ior 1.33 } }
box { <-0.4, 0, -2>, <0.2, 0.5, -1.4> pigment { rgbt <1, 1, 1, 0.9> } normal { quilted 2 scale 0.2 }
      finish { reflection { 0, 1 fresnel } ambient 0 diffuse 0 } interior { ior 1 } }
box { <-2, 0, 1.5>, <-1, 2, 2> pigment { rgb <0.9, 0.2, 0.2> } }
box { <-0.5, 0, 1.5>, <0.5, 2, 2> pigment { rgb <0.2, 0.9, 0.2> } }
box { <1, 0, 1.5>, <2, 2, 2> pigment { rgb <0.2, 0.2, 0.9> } }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.5, 0.5, 0.55> } }
