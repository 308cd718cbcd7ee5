// Exact depth ties between bounded objects: squares whose top faces lie in the top face of a
// board (as in POV-Ray's advanced/pawns.pov), and pillars whose front faces lie in a wall's.
// Each pair is hit at the same depth and its boxes are entered at the same depth, so the order
// in which POV-Ray's bounding tree hands them out (its priority queue, a binary heap) decides
// which colour is seen.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-3, 6, -9> look_at <0.5, -0.5, 0> angle 50 }
light_source { <-20, 40, -30> color rgb 1 }
light_source { <30, 20, -20> color rgb 0.5 }

// the board: its top face at y = 0
box { <-4, -0.5, -4>, <4, 0, 4> pigment { color rgb <0.9, 0.8, 0.5> } }

// squares in a checker pattern reaching down through the board, their tops at y = 0
#declare I = -4;
#while (I < 4)
  #declare J = -4;
  #while (J < 4)
    #if (mod(I + J + 8, 2) = 0)
      box { <I, -1 - 0.1 * mod(I + 4, 3), J>, <I + 1, 0, J + 1>
        pigment { color rgb <0.3 + 0.05 * (I + 4), 0.15, 0.1 + 0.05 * (J + 4)> } }
    #end
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end

// a wall behind the board, its front face at z = 4, and pillars of several depths in it
box { <-4, 0, 4>, <4, 2.5, 4.5> pigment { color rgb <0.4, 0.6, 0.9> } }
#declare K = 0;
#while (K < 6)
  box { <-3.5 + 1.2 * K, 0.25, 4>, <-2.9 + 1.2 * K, 2.25, 4.6 + 0.3 * K>
    pigment { color rgb <0.9, 0.3 + 0.1 * K, 0.2> } }
  #declare K = K + 1;
#end
