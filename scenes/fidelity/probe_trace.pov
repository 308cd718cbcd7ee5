// trace(): small spheres dropped onto a torus and a CSG along -y, each placed at the hit point
// and pushed out along the normal trace returns; misses return <0,0,0> and a zero normal
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -6> look_at <0, 0, 0> }
light_source { <3, 8, -4> rgb 1 }
plane { y, -1 pigment { checker rgb 0.3 rgb 0.7 } }
#declare Ring = torus { 1.2, 0.4 rotate 15*x translate <-1.2, 0, 0.5> };
#declare Lump = difference { box { <0.5, -1, -0.5>, <2.5, 0.5, 1.5> } sphere { <1.5, 0.6, 0.5>, 0.8 } };
object { Ring pigment { rgb <0.9, 0.6, 0.3> } }
object { Lump pigment { rgb <0.4, 0.6, 0.9> } }
#declare N = <0, 0, 0>;
#declare I = 0;
#while (I < 14)
  #declare J = 0;
  #while (J < 10)
    #declare Start = <-3 + I * 0.4, 5, -1 + J * 0.35>;
    #declare P = trace(Ring, Start, -y, N);
    #if (vlength(N) > 0) sphere { P + 0.08 * N, 0.08 pigment { rgb <1, 0.2, 0.2> } } #end
    #declare P = trace(Lump, Start, <0.1, -1, 0>, N);
    #if (vlength(N) > 0) sphere { P + 0.08 * N, 0.08 pigment { rgb <0.2, 1, 0.2> } } #end
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
