#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, rgb 1 }
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { 121111111111111, <0, 1, 2> }
}
// (found by fuzzing) The announced count made room for 50,000,000 faces (1.6 GB) before any face
// was read, beyond the memory limit: "the scene needs more memory than the system gives povml".
