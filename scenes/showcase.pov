// povml showcase scene (render at 640x480; e.g. +W640 +H480 +A0.3).
// A mirror ball, a glass ball, a few coloured balls on a glossy floor under a blue sky, two lights.
// Uses only the povml subset (docs/povray-rules.md §1-§9).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }

#declare Glass = texture {
  pigment { rgbf <0.97, 1, 0.98, 0.93> }
  finish { ambient 0 diffuse 0.03 phong 0.9 phong_size 200 reflection { 0.02, 0.9 fresnel } conserve_energy }
};
#declare Chrome = texture {
  pigment { rgb <0.55, 0.57, 0.6> }
  finish { ambient 0 diffuse 0.1 specular 0.9 roughness 0.01 reflection { 0.75 metallic } }
};
#declare Glossy = finish { ambient 0.08 diffuse 0.7 phong 0.6 phong_size 60 reflection 0.05 };

camera { location <0, 2.1, -7.5> look_at <0, 0.9, 0> right x*image_width/image_height angle 52 }
sky_sphere { pigment { rgb <0.45, 0.62, 0.9> } }
light_source { <-6, 9, -6>, rgb <1, 0.97, 0.9> }
light_source { < 7, 5, -4>, rgb <0.35, 0.4, 0.5> }

sphere { <-1.7, 1.25, 0.8>, 1.2 texture { Chrome } }
sphere { <0.55, 0.98, -1.1>, 0.9 texture { Glass } interior { ior 1.5 fade_distance 2 fade_power 2 fade_color rgb <0.6, 0.9, 0.8> } }
sphere { < 2.4, 0.75, 1.3>, 0.7 pigment { rgb <0.85, 0.2, 0.15> } finish { Glossy } }
sphere { < 1.1, 0.45, 2.6>, 0.4 pigment { rgb <0.95, 0.75, 0.1> } finish { Glossy } }
sphere { <-0.6, 0.35, -2.3>, 0.3 pigment { rgb <0.2, 0.45, 0.95> } finish { Glossy } }
sphere { < 2.3, 0.3, -1.6>, 0.25 pigment { rgb <0.25, 0.8, 0.35> } finish { Glossy } }
sphere { <-3.6, 0.5, -0.9>, 0.45 pigment { rgb <0.6, 0.25, 0.8> } finish { Glossy } }
sphere { < 0.9, 1.45, 6.5>, 1.35 pigment { rgb <0.95, 0.55, 0.2> } finish { Glossy } }
plane { y, 0 pigment { rgb <0.72, 0.7, 0.66> } finish { ambient 0.06 diffuse 0.75 reflection { 0.04, 0.35 falloff 2 } } }
