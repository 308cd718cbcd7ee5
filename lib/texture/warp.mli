(** Warps of pattern space (warps.cpp): what happens to a point before a pattern is evaluated,
    bit-exact to POV-Ray 3.7.0.10. *)

val point : Scene.warp list -> Scene.pattern -> Vec.t -> Vec.t
(** [point ws pat p] is [p] taken through the warps [ws] from the head (POV-Ray's Warp_EPoint;
    the head is the last warp written): transforms by their inverse, turbulence (the point plus
    [Noise.dturbulence] times the amount), repeat, black holes (their repeat blocks and
    uncertainty drawn from [Noise.random_double] at the block's [Noise.hash3d]), and the
    cylindrical, spherical, toroidal, planar and cubic mappings. A [Classic_turb] is skipped when
    [pat] is [Marble] or [Wood], which apply it themselves. Every coordinate of the result is
    then clamped to ±1e17, as POV-Ray does after the last warp. *)

val classic_turb : Scene.warp list -> Scene.turb option
(** [classic_turb ws] is the [turbulence] written directly in the pattern (Search_For_Turb: the
    list's last element when it is a [Classic_turb]). *)

val default_turb : Scene.turb
(** [default_turb] is a new turbulence as POV-Ray creates it (Create_Warp): amount 0, 6 octaves,
    omega 0.5, lambda 2. *)
