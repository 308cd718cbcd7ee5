(** What pigments and normals share when they are read (POV-Ray 3.7's Parse_Pattern and
    Parse_Warp): the pattern keyword with its arguments, the pattern modifiers, turbulence and
    warps. A pattern is read as POV-Ray reads it: the pattern first, then modifiers, each editing
    the pattern read so far. *)

(** Whether the pattern is read for a pigment or a normal (facets is a normal's only). *)
type kind = Pigment_pattern | Normal_pattern

(** The part of a pigment or normal that every pattern has, as it is being read. *)
type header = {
  pat : Scene.pattern option;  (** None until a pattern keyword (a plain colour) *)
  frequency : float;  (** single precision *)
  phase : float;  (** single precision *)
  wave : Scene.wave;
  warps : Scene.warp list;  (** the head is the last written; the classic turbulence is last *)
  noise : int;  (** 0: the scene's noise generator *)
}

val plain : header
(** [plain] is the header of a new pigment or normal: no pattern, frequency 1, phase 0, ramp
    wave, no warps, the scene's noise generator (Init_TPat_Fields). *)

val uv : Reader.st -> string -> float * float
(** [uv st what] reads a 2-term vector (a float stands for both terms, a longer vector gives its
    first two); [what] names it in the error. *)

val parse_warp : Reader.st -> Scene.warp list -> Scene.warp list
(** [parse_warp st ws] reads [{ … }] after [warp] and pushes the warp on the head of [ws], with
    POV-Ray's checks (one repeat axis, Check_BH_Parameters for a repeated black hole). *)

val pattern_keyword : Reader.st -> kind -> header -> header option
(** [pattern_keyword st kind h] reads a pattern keyword that takes no list of colours, pigments or
    normals, with its arguments, into [h] (its default wave and frequency set, agate's classic
    turbulence added); None when the next token is not one. Patterns povml lacks are
    [not supported yet] at their keyword. *)

val modifier : Reader.st -> header -> header option
(** [modifier st h] reads one pattern modifier into [h]: turbulence, octaves, omega, lambda,
    warp, a transform, frequency, phase, a wave type, noise_generator, or one of the pattern's own
    fields (agate_turb, brick_size, mortar, crackle's form/metric/offset/solid, facets' coords/
    size/metric, quilted's controls, a fractal's exponent/interior/exterior, pavement's fields);
    None when the next token is not a modifier. A field of another pattern is a located error. *)

val finish : Reader.st -> Loc.t -> header -> header
(** [finish st loc h] makes the checks POV-Ray's Parse_Pattern makes at its end (pavement's
    sides, tiles and pattern numbers, with interior, exterior and form reduced; the tiling number)
    with errors at [loc]. *)
