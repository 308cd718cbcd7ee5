// povml fidelity scene: lang_arrays_switch
// Rule: arrays with initialisers (one and two dimensions), element assignment, dimension_size;
//       #switch with #case, #range, #else and fall-through; #for with a negative step; string
//       functions checked with #if/#error; #ifdef/#undef; #local in an include-free macro
//       (docs/povray-rules.md §11.2, §11.3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.5, 0.5> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6>, rgb 1 }
plane { y, 0 pigment { rgb 0.7 } }
#declare Colours = array[4] { rgb <1, 0.3, 0.2>, rgb <0.2, 0.8, 0.3>, rgb <0.2, 0.4, 1>, rgb <0.9, 0.8, 0.2> }
#declare Heights = array[2][3] { { 0.3, 0.5, 0.7 }, { 0.9, 1.1, 1.3 } }
#declare Heights[1][2] = 1.6;
#for (I, dimension_size(Heights, 2) - 1, 0, -1)
  #for (J, 0, 1)
    #switch (I + J)
      #case (0)
        #declare C = Colours[0];
        #break
      #range (1, 2)
        #declare C = Colours[1];
        // no #break: falls through into the #else body
      #else
        #declare C = Colours[3] * 0.8 + Colours[2] * 0.2;
    #end
    sphere { <(I - 1) * 2, Heights[J][I], J * 2 - 0.5>, 0.3 + Heights[J][I] / 4 pigment { C } }
  #end
#end
#declare Name = concat("row", str(2, 0, 0), "-", strupr("ok"));
#if (strcmp(Name, "row2-OK") != 0 | strlen(Name) != 7 | substr(Name, 4, 1) != "2")
  #error concat("string functions disagree: ", Name)
#end
#declare Extra = 1;
#undef Extra
#ifndef (Extra)
  sphere { <0, 0.25, -2>, 0.25 pigment { Colours[dimension_size(Colours, 1) - 1] } finish { phong 1 } }
#end
