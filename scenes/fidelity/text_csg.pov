// text in CSG: engraved into a box (difference), cut by a sphere (intersection), a merged glass word
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.3, 1.6, -4.5> look_at <0.5, 0.2, 0> angle 55 }
light_source { <-5, 8, -7>, rgb 1 }
light_source { <4, 3, -6>, rgb 0.3 shadowless }
plane { y, -1 pigment { checker rgb 0.85 rgb <0.4, 0.45, 0.5> scale 0.5 } }
difference {
  box { <-1.5, -0.2, -0.1>, <2.6, 0.9, 0.5> }
  text { ttf "cyrvetic.ttf" "Engrave", 0.3, 0 translate <-1.3, 0, -0.2> }
  pigment { rgb <0.85, 0.75, 0.5> }
}
intersection {
  text { ttf "timrom.ttf" "Sphere", 2, 0 scale 1.2 translate <-1.6, -0.9, -1.8> }
  sphere { <0, -0.4, -1>, 1.1 }
  pigment { rgb <0.8, 0.2, 0.3> }
}
merge {
  text { ttf "cyrvetic.ttf" "oo", 0.4, <-0.15, 0, 0> }
  sphere { <0.5, 0.35, 0.2>, 0.2 }
  translate <1.3, -0.95, -1.6>
  pigment { rgbf <0.9, 1, 0.95, 0.8> } finish { phong 0.8 } interior { ior 1.4 }
}
text { ttf "cyrvetic.ttf" "inv", 0.2, 0 inverse translate <1.6, 1.05, 0> pigment { rgb <0.2, 0.6, 0.3> } }
