(** Warps of pattern space (warps.cpp): what happens to a point before a pattern is evaluated. *)

val point : Scene.warp list -> Scene.pattern -> Vec.t -> Vec.t
(** [point ws pat p] is [p] taken through the warps [ws] from the head (POV-Ray's Warp_EPoint):
    transforms by their inverse, turbulence, repeat, black holes, the mapping warps. A
    [Classic_turb] is skipped when [pat] is [Marble] or [Wood], which apply it themselves. *)

val classic_turb : Scene.warp list -> Scene.turb option
(** [classic_turb ws] is the [turbulence] written directly in the pattern (Search_For_Turb: the
    list's last element when it is a [Classic_turb]). *)
