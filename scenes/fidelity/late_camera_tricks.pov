// Written after the code: a camera with sky tilt, a non-default up/right and direction, declared
// objects moved with translate, emission, ambient_light and a sky_sphere with two layered pigments.
#version 3.7;
global_settings { assumed_gamma 2.2 ambient_light rgb <0.8, 0.9, 1> }
#declare Ball = sphere { 0, 0.5 pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.7 emission rgb <0.05, 0.02, 0> } };
#declare Step = 1.1;
camera { location <3, 2, -5> look_at <0, 0.5, 0> sky <0.3, 1, 0> up y*1.2 right x*1.6 direction z*1.5 }
sky_sphere { pigment { rgbt <0.2, 0.3, 0.9, 0.4> } pigment { rgb <0.9, 0.9, 0.7> } }
light_source { <-3, 6, -6>, rgb 1 }
object { Ball translate <-Step, 0.5, 0> }
object { Ball translate <0, 0.5, Step> pigment { rgb <0.3, 0.7, 0.9> } }
object { Ball translate <Step, 0.5, 0> finish { reflection 0.5 } }
object { Ball translate <0, 0.5 + Step, 0> no_shadow }
plane { <0.1, 1, 0>, -0.1 pigment { rgb 0.6 } finish { reflection { 0.1 } } }
