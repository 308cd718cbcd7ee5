// POV-Ray 3.7.0.10's image_map, image_pattern values at a few points, for test/unit/test_images.ml.
// Run from the repository root: povray +Itest/unit/data/images.pov +W8 +H8 -D -GA 2>&1 | grep '^V'
#version 3.7;
global_settings { assumed_gamma 1 }
#declare Pts = array[4] { <0.03, 0.97, 0>, <0.5, 0.5, 0>, <0.77, 0.123, 0>, <-1.3, 2.71, 0> };
#macro Show(Name, F)
  #for (I, 0, 3)
    #local P = Pts[I];
    #local C = F(P.x, P.y, P.z);
    #debug concat("V ", Name, " ", str(I, 0, 0), " ", str(C.red, 0, 16), " ", str(C.green, 0, 16), " ", str(C.blue, 0, 16), " ", str(C.filter, 0, 16), " ", str(C.transmit, 0, 16), "\n")
  #end
#end
#declare F1 = function { pigment { image_map { png "scenes/images/rgb8.png" } } }
Show("rgb8", F1)
#declare F2 = function { pigment { image_map { png "scenes/images/rgb16.png" interpolate 2 } } }
Show("rgb16_bilinear", F2)
#declare F3 = function { pigment { image_map { png "scenes/images/pal.png" interpolate 4 } } }
Show("pal_normdist", F3)
#declare F4 = function { pigment { image_map { png "scenes/images/grey.png" } } }
Show("grey", F4)
#declare F5 = function { pigment { image_map { png "scenes/images/alpha.png" once } } }
Show("alpha_once", F5)
#declare F6 = function { pigment { image_map { jpeg "scenes/images/img.jpg" } } }
Show("jpeg", F6)
#declare F7 = function { pigment { image_map { gif "scenes/images/img.gif" transmit 3, 0.5 filter all 0.25 } } }
Show("gif_ft", F7)
#declare F8 = function { pigment { image_pattern { png "scenes/images/rgb8.png" interpolate 2 } } }
Show("pattern", F8)
#declare F9 = function { pigment { image_map { ppm "scenes/images/img.ppm" interpolate 3 } } }
Show("ppm_bicubic", F9)
#declare F10 = function { pigment { image_map { tga "scenes/images/img.tga" map_type 1 } } }
Show("tga_spherical", F10)
camera { location -z look_at 0 }
