// povml fidelity scene: lang_includes
// Rule: POV-Ray's standard include files read as they are (docs/povray-rules.md §11.3): colors.inc,
//       textures.inc (with finish.inc), metals.inc and glass.inc, using their plain-colour pigments,
//       finishes, textures and interiors; everything else they declare is never used.
#version 3.7;
#include "colors.inc"
#include "textures.inc"
#include "metals.inc"
#include "glass.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7> look_at <0, 0.7, 0> right x*image_width/image_height angle 48 }
light_source { <-4, 6, -5>, White }
light_source { <5, 4, -3>, Gray50 shadowless }
plane { y, 0 pigment { Tan } finish { Dull } }
sphere { <-2.4, 0.8, 0>, 0.8 pigment { Red } finish { Shiny } }
sphere { <-0.8, 0.8, 0.6>, 0.8 pigment { MediumAquamarine } finish { Phong_Glossy } }
sphere { <0.8, 0.8, 0>, 0.8 texture { T_Brass_1A } }
sphere { <2.4, 0.8, 0.6>, 0.8 pigment { color Col_Glass_Clear } finish { Glass_Finish } interior { Glass_Interior } }
sphere { <0, 0.35, -1.6>, 0.35 texture { Polished_Chrome } }
sphere { <1.6, 0.3, -1.5>, 0.3 pigment { P_Brass4 } finish { F_MetalA } }
sphere { <-1.6, 0.3, -1.5>, 0.3 pigment { SkyBlue filter 0.5 } finish { F_Glass1 } interior { I_Glass1 } }
