(** POV-Ray 3.7's solid noise and its vector noise, and the turbulence built on them
    (texture.cpp: Noise, DNoise, Turbulence, DTurbulence), with POV-Ray's own hash and random
    tables. Every function is pure; the tables are built once when the module is loaded. *)

val noise : int -> Vec.t -> float
(** [noise gen p] is POV-Ray's scalar noise at [p] with noise generator [gen]: 1 (the original,
    clipped), 2 (the range-corrected one, 3.7's default) or 3 (Perlin's improved noise). The value
    is in [0, 1]. *)

val dnoise : Vec.t -> Vec.t
(** [dnoise p] is POV-Ray's vector noise at [p] (each component in about [-1, 1]). *)

val turbulence : Scene.turb -> int -> Vec.t -> float
(** [turbulence t gen p] is the sum over [t.octaves] octaves of [noise] at [p] scaled by powers of
    [t.lambda], weighted by powers of [t.omega], as POV-Ray's Turbulence (the amount vector
    [t.turbulence] is not used here). *)

val dturbulence : Scene.turb -> Vec.t -> Vec.t
(** [dturbulence t p] is the vector turbulence (DTurbulence): octaves of [dnoise]; a warp scales
    it by the amount vector. *)

val hash3d : int -> int -> int -> int
(** [hash3d a b c] is POV-Ray's Hash3d of three integers (each taken modulo 4096): 0…4095. *)

val hash2d : int -> int -> int
(** [hash2d a b] is POV-Ray's Hash2d (arguments 0…8191). *)

val random_double : int -> float
(** [random_double i] is the [i]th value (taken modulo 32768, [i] ≥ 0) of POV-Ray's
    RandomDoubleSequence(0, 1, 32768), the table behind PatternRands and WarpRands. *)

val wave_source : int -> Vec.t
(** [wave_source i] is the centre of the [i]th (from 0) wave of the waves and ripples patterns. *)

val wave_frequency : int -> float
(** [wave_frequency i] is the frequency of the [i]th wave, in [0.01, 1.01). *)
