(** The noise-based internal functions of POV-Ray 3.7 (fnintern.cpp) on {!Noise}: f_hetero_mf
    (29), f_ridge (58), f_ridged_mf (59), f_noise3d (76) and f_noise_generator (78). *)

val make : noise_generator:int -> int -> (float array -> float) option
(** [make ~noise_generator k] is a fresh function of [internal(k)] for those five [k], else
    [None]. f_noise3d uses [noise_generator], the scene's; the others take theirs from their
    last parameter, (int)p & 3 (0 behaving as 1). The function of f_ridged_mf keeps the octave
    weights its first call computes, whatever the parameters of later calls, as POV-Ray does. *)
