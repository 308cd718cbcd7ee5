// POV-Ray 3.7.0.10's trace() of height fields, printed for test/unit/test_hfield.ml
// (run from the repository root: povray +Itest/unit/data/hfield.pov +L. +W8 +H8 -D)
#version 3.7;
global_settings { assumed_gamma 1 }
#declare Flat = height_field { png "scenes/images/hf_grey8.png" }
#declare Smooth = height_field { png "scenes/images/hf_grey16.png" smooth scale <2, 0.5, 1> rotate y*30 }
#macro T(Obj, O, D)
#declare N = <0,0,0>;
#declare P = trace(Obj, O, D, N);
#debug concat("p ", vstr(3, P, " ", 0, 17), "\n")
#debug concat("n ", vstr(3, N, " ", 0, 17), "\n")
#end
T(Flat, <-0.2, 0.45, 0.5>, <0.96087257926379466, 0.1703210656168497, 0.21843676665360973>)
T(Flat, <-0.2, 0.45, 0.5>, <0.94147652444244967, -0.24862159092761274, 0.22761647226944762>)
T(Smooth, <0.3, 1.5, -1>, <0.2, -0.8, 0.6>)
T(Smooth, <-0.5, 0.3, 0.2>, <1, -0.1, 0.05>)
