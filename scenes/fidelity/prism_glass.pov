// povml fidelity scene: prism_glass
// Rule: a glass prism: refraction in and out through the caps and the spline sides (the normal and the inside rule), with reflection
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
#declare Glass = material { texture { pigment { rgbf <1,1,1,0.9> } finish { specular 0.6 reflection 0.05 } } interior { ior 1.5 } }
prism { cubic_spline 0, 1.2, 8, <0,-1.2>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1>, <-1, 0.3> material { Glass } translate <-1.2, 0.1, 0> }
prism { conic_sweep bezier_spline 0.4, 1, 8, <0,0>,<0.8,0>,<0.8,0.8>,<0,0.8>, <0,0.8>,<-0.8,0.8>,<-0.8,0>,<0,0> material { Glass } rotate x*180 scale 1.3 translate <1.4, 1.4, 0> }
