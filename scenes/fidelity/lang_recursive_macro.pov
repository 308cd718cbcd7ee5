// povml fidelity scene: lang_recursive_macro
// Rule: #macro with parameters, #local, recursion, a macro that returns a value and one that
//       returns an object, by-reference arguments (docs/povray-rules.md §11.3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1.2, 0> right x*image_width/image_height angle 45 }
light_source { <-5, 8, -6>, rgb 1 }
light_source { <5, 3, -6>, rgb 0.35 }
plane { y, 0 pigment { rgb <0.6, 0.65, 0.7> } finish { reflection 0.15 } }
#macro Shade(Level) <1 - Level / 5, 0.3 + Level / 8, Level / 4> #end
#macro Ball(P, R, Level) sphere { P, R pigment { rgb Shade(Level) } finish { phong 0.6 } } #end
#declare Count = 0;
#macro Flake(P, R, Level, Counter)
  Ball(P, R, Level)
  #declare Counter = Counter + 1;
  #if (Level < 3)
    #local K = 0;
    #while (K < 4)
      #local D = vrotate(<1, 0.35, 0>, <0, 90 * K + 45 * Level, 0>);
      Flake(P + D * R * 1.45, R * 0.45, Level + 1, Counter)
      #local K = K + 1;
    #end
  #end
#end
Flake(<0, 1.2, 0>, 1, 0, Count)
// the counter came back through the by-reference argument: 1 + 4 + 16 + 64 = 85 spheres
#if (Count != 85) #error concat("expected 85 spheres, got ", str(Count, 0, 0)) #end
sphere { <3.5, 0.3, -1.5>, 0.3 pigment { rgb Shade(Count / 40) } }
