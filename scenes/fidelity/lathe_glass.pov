// povml fidelity scene: lathe_glass
// Rule: a glass lathe (cubic spline, degree-6 Sturm solve): refraction through the curved wall, the inside rule
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
#declare Glass = material { texture { pigment { rgbf <1,1,1,0.9> } finish { specular 0.6 reflection 0.05 } } interior { ior 1.5 } }
lathe { cubic_spline 7, <0,-0.5>, <0,0>, <1,0.2>, <0.4,1>, <0.8, 1.6>, <0, 2>, <0, 2.5> material { Glass } translate <-1.2, 0, 0> }
lathe { bezier_spline 8, <0,0>, <1,0>, <1,1>, <0.5,1>, <0.5,1>, <0,1>, <0.8,2>, <0,2> material { Glass } translate <1.3, 0, 0> }
