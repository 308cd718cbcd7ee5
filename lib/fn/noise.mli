(** POV-Ray 3.7's solid noise, its vector noise and the turbulence built on them (texture.cpp:
    Noise, DNoise, Turbulence, DTurbulence), with POV-Ray's own hash, gradient and random tables,
    and the other pieces of texture.cpp that patterns use (the wave sources, cycloidal,
    Triangle_Wave). Every function is pure and bit-exact to POV-Ray 3.7.0.10 on x86-64: the same
    operations in the same order, C's truncating casts and 32-bit masks included. The tables are
    built once when the module is loaded. Apart from their result (a boxed float, a [Vec.t]) the
    functions allocate nothing, except a three-float scratch record in [dnoise] and
    [dturbulence]. *)

(** Turbulence: the amount per axis, octaves (1…10, 6 by default), omega (0.5) and lambda (2),
    the last two in single precision (the scene's [turb]). *)
type turb = { turbulence : Vec.t; octaves : int; omega : float; lambda : float }

val noise : int -> Vec.t -> float
(** [noise gen p] is POV-Ray's scalar noise at [p] with noise generator [gen]: 1 (the original
    lattice noise, plus 0.5 and clipped), 2 (the same, range-corrected: 3.7's default) or 3
    (Perlin's "solid noise", bias-corrected). Any other [gen] behaves as 1, as in POV-Ray (whose
    f_noise_generator can pass 0). The value is in [0, 1]. A pattern's generator 0 ("the
    scene's") must be resolved by the caller. *)

val dnoise : Vec.t -> Vec.t
(** [dnoise p] is POV-Ray's vector noise at [p] (DNoise, each component roughly in [-1, 1]). It
    is the same for every noise generator: POV-Ray has no vector form of generator 3. *)

val turbulence : turb -> int -> Vec.t -> float
(** [turbulence t gen p] is POV-Ray's Turbulence with generator [gen]: [noise] at [p] plus, for
    each octave i from 2 to [t.octaves], [t.omega]^(i−1) times [noise] at [t.lambda]^(i−1)·[p].
    Generators 2 and 3 use 2·noise − 0.5 in every octave, the first clipped to [0, 1]. The
    amount [t.turbulence] is not applied: marble, spiral and agate scale the result themselves.
    [t.omega] and [t.lambda] must be single precision, as POV-Ray stores them. *)

val dturbulence : turb -> Vec.t -> Vec.t
(** [dturbulence t p] is POV-Ray's DTurbulence: the octaves of [turbulence] with [dnoise] in
    place of [noise]; one octave is [dnoise p] itself. The amount vector is not applied (a
    turbulence warp multiplies by it). *)

val hash3d : int -> int -> int -> int
(** [hash3d a b c] is POV-Ray's Hash3d, 0…4095; each argument is taken modulo 4096 (its low
    12 bits, negative numbers included). *)

val hash2d : int -> int -> int
(** [hash2d a b] is POV-Ray's Hash2d, 0…4095, for [a] and [b] in 0…8191 (not checked). *)

val random_double : int -> float
(** [random_double i] is the [i]th value (taken modulo 32768, [i] ≥ 0) of POV-Ray's
    RandomDoubleSequence(0, 1, 32768), the table behind PatternRands (cells, crackle) and
    WarpRands (black-hole uncertainty): Boost's mt19937 with its default seed, in [0, 1). *)

val wave_source : int -> Vec.t
(** [wave_source i] is the centre of the [i]th (from 0) wave of the waves and ripples patterns and
    normals: [dnoise <i, 0, 0>] divided by its length (Initialize_Waves). *)

val wave_frequency : int -> float
(** [wave_frequency i] is the frequency of the [i]th wave, in [0.01, 1.01) (Initialize_Waves). *)

val wave_sources : int -> Vec.t array
(** [wave_sources n] holds at least [n] wave sources: [wave_source i] at index [i]. *)

val wave_frequencies : int -> float array
(** [wave_frequencies n] holds at least [n] wave frequencies: [wave_frequency i] at index [i]. *)

val cycloidal : float -> float
(** [cycloidal v] is POV-Ray's cycloidal: sin(2π·frac v) for [v] ≥ 0, −cycloidal(−v) below. *)

val triangle_wave : float -> float
(** [triangle_wave v] is POV-Ray's Triangle_Wave: 2·frac v below a half, 2·(1 − frac v) from it. *)
