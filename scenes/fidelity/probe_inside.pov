// inside(): a grid of points kept where they lie inside a CSG (a merge with a hole), and
// min_extent()/max_extent() centring a text object and framing it with its box
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0.3, 0> }
light_source { <3, 8, -6> rgb 1 }
plane { y, -1 pigment { checker rgb 0.3 rgb 0.7 } }
#declare Shape = difference { merge { sphere { <-1.5, 0, 0>, 1 } cylinder { <-1.5, -1, 0>, <-1.5, 1.2, 0>, 0.4 } } sphere { <-1.5, 0.2, -0.8>, 0.5 } };
#declare I = 0;
#while (I < 12)
  #declare J = 0;
  #while (J < 12)
    #declare K = 0;
    #while (K < 6)
      #declare P = <-2.7 + I * 0.22, -1 + J * 0.22, -1.2 + K * 0.4>;
      #if (inside(Shape, P)) sphere { P, 0.07 pigment { rgb <1, 0.5, 0.2> } } #end
      #declare K = K + 1;
    #end
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
#declare Word = text { ttf "timrom.ttf" "Box" 0.3, 0 scale 0.9 rotate -10*y };
#declare Lo = min_extent(Word);
#declare Hi = max_extent(Word);
object { Word translate -(Lo + Hi) / 2 translate <1.6, 0.5, 0> pigment { rgb <0.3, 0.5, 1> } }
box { Lo, Hi translate -(Lo + Hi) / 2 translate <1.6, 0.5, 0> pigment { rgbt <1, 1, 1, 0.8> } }
