#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
#declare I = 0;
#while (true) sphere { <I, 0, 0>, 1 } #declare I = I + 1; #end
