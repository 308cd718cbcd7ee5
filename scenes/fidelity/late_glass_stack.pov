// Written after the code: a stack of glass and mirror spheres over a fading glass slab of spheres,
// two coloured lights, one fading, and a filtered shadow through coloured glass.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 adc_bailout 0.01 }
camera { location <1.5, 2.5, -6> look_at <0, 0.8, 0> right x*image_width/image_height angle 60 }
background { rgb <0.2, 0.25, 0.3> }
light_source { <-5, 8, -3>, rgb <1, 0.9, 0.8> }
light_source { <3, 4, -5>, rgb <0.3, 0.4, 0.9> fade_distance 4 fade_power 1 }
#declare G = texture { pigment { rgbf <0.8, 0.95, 1, 0.85> } finish { ambient 0.02 diffuse 0.05 specular 0.8 roughness 0.005 reflection { 0.05, 0.6 fresnel } } };
sphere { <0, 0.9, 0>, 0.9 texture { G } interior { ior 1.45 fade_distance 1.5 fade_power 1001 fade_color <0.7, 0.9, 1> } }
sphere { <0, 0.9, 0>, 0.4 pigment { rgbt <1, 0.6, 0.2, 0.6> } interior { ior 1.2 } }
sphere { <-1.6, 0.55, 1.0>, 0.55 pigment { rgb <0.7, 0.7, 0.75> } finish { ambient 0 diffuse 0.15 reflection { 0.5, 0.95 falloff 3 } metallic phong 1 phong_size 150 } }
sphere { <1.7, 0.4, 0.6>, 0.4 pigment { color red 0.2 green 0.8 blue 0.3 } finish { brilliance 2.5 specular 0.4 roughness 0.05 } }
sphere { <0.9, 1.9, 1.8>, 0.35 pigment { rgbf <1, 0.2, 0.2, 0.7> } finish { conserve_energy reflection 0.3 } }
plane { y, 0 pigment { rgb <0.85, 0.82, 0.78> } finish { diffuse 0.8 reflection 0.1 } }
