// povml fidelity scene: lang_transforms_groups
// Rule: transforms on objects, unions and lights (docs/povray-rules.md §14): a union with a shared
//       texture, a light inside it and a transform after it (§16.4, §19.1); object copies with
//       their own transforms (§19.3); declared transforms, transform blocks with inverse (§14.3);
//       rotated triangles and a scaled smooth triangle; #for loops placing rotated copies.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 48 }
light_source { <-6, 9, -7>, rgb 0.9 }
plane { y, 0 pigment { rgb <0.75, 0.75, 0.7> } }
#declare Pair = union {
  sphere { <-0.5, 0, 0>, 0.45 }
  sphere { <0.5, 0, 0>, 0.45 pigment { rgb <0.9, 0.8, 0.2> } }
  light_source { <0, 2.5, -1>, rgb <0.4, 0.3, 0.3> }
  pigment { rgb <0.2, 0.5, 0.9> }
  finish { phong 0.7 }
}
object { Pair rotate <0, 0, 30> translate <-2.5, 1.2, 0> }
object { Pair scale <1, 1.5, 1> rotate <0, 45, 0> translate <0, 0.7, 1.5> }
#declare Tilt = transform { rotate <20, 0, 10> translate <0, 0.5, 0> }
#declare Back = transform { Tilt inverse }
sphere { 0, 0.5 scale <1.4, 0.6, 1> transform Tilt translate <2.6, 0.5, -0.5> pigment { rgb <0.9, 0.3, 0.3> } }
sphere { <2.6, 1.8, 0.5>, 0.4 transform { Tilt } transform Back pigment { rgb <0.3, 0.9, 0.4> } }
#for (K, 0, 5)
  triangle { <0, 0, 0>, <0.5, 0, 0>, <0, 0.35, 0>
    translate <0.35, 0.05, 0> rotate <0, 0, 60 * K> rotate <90, 0, 0> translate <0, 0.02, -2.2>
    pigment { rgb <K / 5, 0.4, 1 - K / 5> } }
#end
smooth_triangle { <-1, 0, 0>, <0, 0, -1>, <1, 0, 0>, <0, 0, -1>, <0, 1, 0>, <0, 0.5, -1>
  scale <1.2, 1, 1> rotate <0, -20, 0> translate <-3.2, 0, -1.5> pigment { rgb <0.8, 0.5, 0.9> } }
