#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
// An infinite sphere among four others (found by fuzzing): its bounding box is infinite and its
// centre NaN, and the hierarchy's binning once indexed its bins with a negative number for the
// sphere read before it (memory corruption). It renders.
sphere { <-2, 0, 0>, 0.5 pigment { rgb 1 } }
sphere { 0, -1e400 pigment { rgb 1 } }
sphere { <1, 0, 0>, 0.5 pigment { rgb 1 } }
sphere { <2, 0, 0>, 0.5 pigment { rgb 1 } }
sphere { <3, 0, 0>, 0.5 pigment { rgb 1 } }
