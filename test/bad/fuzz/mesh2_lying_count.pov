#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
// (found by fuzzing) A count far above the entries that follow: room for the announced entries was
// made first, up to 50 million of them (1.6 GB for faces), before the wrong count could be reported.
// The room made in advance is now bounded by the memory limit.
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 1, texture { pigment { rgb 1 } } }
  face_indices { 121111111111111, <0,1,2>, 0 }
}
