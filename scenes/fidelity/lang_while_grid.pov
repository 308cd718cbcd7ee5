// povml fidelity scene: lang_while_grid
// Rule: #while loops with #declare counters, nested loops, seed()/rand() streams, colour arithmetic
//       and #if inside the loop body (docs/povray-rules.md §11.2, §11.3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -9> look_at <0, 0, 0.5> right x*image_width/image_height angle 50 }
light_source { <-6, 10, -8>, rgb 1 }
light_source { <6, 6, -4>, rgb 0.3 shadowless }
plane { y, -0.5 pigment { rgb <0.8, 0.8, 0.75> } }
#declare S = seed(1234);
#declare N = 7;
#declare I = 0;
#while (I < N)
  #declare J = 0;
  #while (J < N)
    #declare R = 0.2 + 0.2 * rand(S);
    #declare C = <I / (N - 1), rand(S), J / (N - 1)>;
    sphere { <(I - (N - 1) / 2) * 1.1, R - 0.5, (J - (N - 1) / 2) * 1.1>, R
      pigment { rgb C }
      #if (mod(I + J, 2) = 0)
        finish { phong 0.8 phong_size 40 }
      #else
        finish { specular 0.5 roughness 0.02 reflection 0.1 }
      #end
    }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
