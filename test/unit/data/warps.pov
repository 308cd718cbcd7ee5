// Each warp type on gradient x, y and z with frequency 0: the value is the warped coordinate
// (above 1 reduced by fmod 1, negatives wrapped into [0,1)). The marble lines show that marble
// skips the classic turbulence in the warps (it is x + 0.3·Turbulence(p) at the unwarped point).
// Run: povray +Iwarps.pov +O/tmp/t.png +W8 +H6 -D   (the values go to #debug)
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
camera { location -z look_at 0 }
#declare P = array[14] { <0.3, 0.4, 0.5>, <-0.6, 0.2, 0.9>, <1.7, -2.3, 0.45>, <-3.1, -0.7, -1.9>, <0.05, 1.2, -0.35>, <2.5, 0.5, 2.5>, <-0.25, -1.75, 0.125>, <5.6, 7.8, -9.1>, <1.1, 1.3, 0.9>, <-1.9, 4.2, 1.2>, <7.3, -1.8, -4.9>, <-4.3, 3.3, 2.1>, <9.9, -6.1, -3.7>, <0.6, 0.45, 0.55> }
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x scale <2, 4, 8> rotate <10, 20, 30> translate <0.25, -0.5, 1> frequency 0 } }
#for (I, 0, 13)
  #debug concat("W transform x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y scale <2, 4, 8> rotate <10, 20, 30> translate <0.25, -0.5, 1> frequency 0 } }
#for (I, 0, 13)
  #debug concat("W transform y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z scale <2, 4, 8> rotate <10, 20, 30> translate <0.25, -0.5, 1> frequency 0 } }
#for (I, 0, 13)
  #debug concat("W transform z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x turbulence <0.3, 0.4, 0.5> octaves 3 omega 0.6 lambda 2.5 frequency 0 } }
#for (I, 0, 13)
  #debug concat("W classic x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y turbulence <0.3, 0.4, 0.5> octaves 3 omega 0.6 lambda 2.5 frequency 0 } }
#for (I, 0, 13)
  #debug concat("W classic y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z turbulence <0.3, 0.4, 0.5> octaves 3 omega 0.6 lambda 2.5 frequency 0 } }
#for (I, 0, 13)
  #debug concat("W classic z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { turbulence <0.5, 0.25, 0.75> octaves 4 omega 0.45 lambda 2.2 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W turb x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { turbulence <0.5, 0.25, 0.75> octaves 4 omega 0.45 lambda 2.2 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W turb y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { turbulence <0.5, 0.25, 0.75> octaves 4 omega 0.45 lambda 2.2 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W turb z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { repeat x*0.7 offset <0.1, 0.2, 0.3> flip <1, 0, 0> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W repeat_x x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { repeat x*0.7 offset <0.1, 0.2, 0.3> flip <1, 0, 0> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W repeat_x y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { repeat x*0.7 offset <0.1, 0.2, 0.3> flip <1, 0, 0> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W repeat_x z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { repeat y*1.3 offset <-0.5, 0.25, 0.125> flip <0, 0, 1> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W repeat_y x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { repeat y*1.3 offset <-0.5, 0.25, 0.125> flip <0, 0, 1> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W repeat_y y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { repeat y*1.3 offset <-0.5, 0.25, 0.125> flip <0, 0, 1> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W repeat_y z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { repeat z*0.45 flip <1, 1, 1> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W repeat_z x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { repeat z*0.45 flip <1, 1, 1> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W repeat_z y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { repeat z*0.45 flip <1, 1, 1> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W repeat_z z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { black_hole <0.5, 0.5, 0.5>, 1.2 strength 0.8 falloff 1.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { black_hole <0.5, 0.5, 0.5>, 1.2 strength 0.8 falloff 1.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { black_hole <0.5, 0.5, 0.5>, 1.2 strength 0.8 falloff 1.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { black_hole <0, 0.5, 0>, 2.5 strength 3 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_strong x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { black_hole <0, 0.5, 0>, 2.5 strength 3 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_strong y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { black_hole <0, 0.5, 0>, 2.5 strength 3 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_strong z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { black_hole <0.5, -0.5, 0.5>, 1.5 inverse falloff 2.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_inverse x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { black_hole <0.5, -0.5, 0.5>, 1.5 inverse falloff 2.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_inverse y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { black_hole <0.5, -0.5, 0.5>, 1.5 inverse falloff 2.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_inverse z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { black_hole <0.5, 0.5, 0.5>, 1.2 type 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_type1 x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { black_hole <0.5, 0.5, 0.5>, 1.2 type 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_type1 y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { black_hole <0.5, 0.5, 0.5>, 1.2 type 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_type1 z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { black_hole <1, 1, 1>, 0.9 strength 0.9 repeat <3, 3, 3> turbulence <0.4, 0.3, 0.2> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_repeat x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { black_hole <1, 1, 1>, 0.9 strength 0.9 repeat <3, 3, 3> turbulence <0.4, 0.3, 0.2> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_repeat y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { black_hole <1, 1, 1>, 0.9 strength 0.9 repeat <3, 3, 3> turbulence <0.4, 0.3, 0.2> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_repeat z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { black_hole <1, 0.5, 0.25>, 0.9 repeat <2, 0, 0> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_repeat_x x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { black_hole <1, 0.5, 0.25>, 0.9 repeat <2, 0, 0> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_repeat_x y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { black_hole <1, 0.5, 0.25>, 0.9 repeat <2, 0, 0> } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W bh_repeat_x z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { cylindrical } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cyl x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { cylindrical } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cyl y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { cylindrical } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cyl z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { cylindrical orientation <0, 1, 0> dist_exp 0.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cyl_y x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { cylindrical orientation <0, 1, 0> dist_exp 0.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cyl_y y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { cylindrical orientation <0, 1, 0> dist_exp 0.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cyl_y z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { cylindrical orientation <1, 0, 0> dist_exp 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cyl_x1 x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { cylindrical orientation <1, 0, 0> dist_exp 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cyl_x1 y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { cylindrical orientation <1, 0, 0> dist_exp 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cyl_x1 z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { spherical } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W sph x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { spherical } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W sph y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { spherical } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W sph z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { spherical orientation <1, 1, 0> dist_exp 1.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W sph_o x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { spherical orientation <1, 1, 0> dist_exp 1.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W sph_o y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { spherical orientation <1, 1, 0> dist_exp 1.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W sph_o z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { toroidal major_radius 2 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W tor x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { toroidal major_radius 2 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W tor y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { toroidal major_radius 2 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W tor z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { toroidal orientation <0, 1, 0> dist_exp 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W tor_y x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { toroidal orientation <0, 1, 0> dist_exp 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W tor_y y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { toroidal orientation <0, 1, 0> dist_exp 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W tor_y z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { toroidal orientation <0, 0, -1> dist_exp 0.7 major_radius 0.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W tor_o x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { toroidal orientation <0, 0, -1> dist_exp 0.7 major_radius 0.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W tor_o y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { toroidal orientation <0, 0, -1> dist_exp 0.7 major_radius 0.5 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W tor_o z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { planar } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W planar x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { planar } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W planar y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { planar } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W planar z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { planar <0, 1, 0>, 0.3 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W planar_y x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { planar <0, 1, 0>, 0.3 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W planar_y y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { planar <0, 1, 0>, 0.3 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W planar_y z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { planar <1, 2, 2>, -0.4 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W planar_o x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { planar <1, 2, 2>, -0.4 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W planar_o y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { planar <1, 2, 2>, -0.4 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W planar_o z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { cubic } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cubic x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { cubic } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cubic y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { cubic } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W cubic z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient x warp { repeat x*0.8 flip x } warp { turbulence 0.2 octaves 2 } rotate <0, 0, 30> warp { black_hole <0.2, 0.1, 0>, 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W chain x ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient y warp { repeat x*0.8 flip x } warp { turbulence 0.2 octaves 2 } rotate <0, 0, 30> warp { black_hole <0.2, 0.1, 0>, 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W chain y ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { gradient z warp { repeat x*0.8 flip x } warp { turbulence 0.2 octaves 2 } rotate <0, 0, 30> warp { black_hole <0.2, 0.1, 0>, 1 } frequency 0 } }
#for (I, 0, 13)
  #debug concat("W chain z ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
#ifdef (F) #undef F #end
#declare F = function { pattern { marble turbulence <0.3, 0.4, 0.5> octaves 3 omega 0.6 lambda 2.5 frequency 0 ramp_wave } }
#for (I, 0, 13)
  #debug concat("M ", str(I, 0, 0), " ", str(F(P[I].x, P[I].y, P[I].z), 0, 20), "\n")
#end
