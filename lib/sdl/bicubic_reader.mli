(** The reader of [bicubic_patch] (POV-Ray's Parse_Bicubic_Patch). *)

val bicubic : Reader.st -> Loc.t -> Scene.shape
(** [bicubic st loc] reads, after the block's ['{'], the patch's [type], [flatness], [u_steps],
    [v_steps] (or the old unnamed numbers, with POV-Ray's warning) and [accuracy] (read and
    unused, as POV-Ray does), then the 16 control points: type 2 and above is type 1 with
    POV-Ray's warning, a missing or negative type "Undefined bicubic patch type." at [loc];
    [uv_vectors] (four 2-term vectors, the corners' texture coordinates) ends the options. *)
