(** POV-Ray's [Solve_Polynomial] up to degree 10 (math/polysolv.cpp): after the small leading
    coefficients are dropped, degrees up to 4 are [Polysolv.solve]'s (with Sturm sequences asked
    for), higher degrees go to polysolve, POV-Ray's Sturm-sequence solver, in its order of
    operations. Sphere sweeps need degree 10 (a cubic segment's sides) and 6 (its inside test). *)

type work
(** Room for one solve at a time: a Sturm sequence of up to 11 polynomials of degree 10. *)

val create : unit -> work
(** [create ()] is fresh work room; a [work] must not serve two solves at the same time. *)

val solve : work -> float array -> int -> eps:float -> float array -> int
(** [solve w c n ~eps roots] solves [c.(0)·xⁿ + … + c.(n) = 0] for [n] ≤ 10 as POV-Ray's
    [Solve_Polynomial] with [sturm] true, writing the roots into [roots] (room for [n]) and
    returning their number. Above degree 4 the roots are those in [0, 1e7]; a constant term tiny
    against the linear one ([eps]) is counted as an eliminated root, but the full polynomial is
    solved all the same, as POV-Ray does. Raises [Invalid_argument] for [n] > 10. *)

val sturm : work -> float array -> int -> int -> float array -> int -> int
(** [sturm w c i n y j] is polysolve: the roots in [0, 1e7] of the degree-[n] polynomial whose
    coefficients start at [c.(i)] (highest power first), written from [y.(j)]. *)

val eval : float array -> int -> int -> float -> float
(** [eval c i n x] is the degree-[n] polynomial with coefficients from [c.(i)] at [x], by
    Horner's rule. For tests. *)

val eliminated : work -> bool
(** [eliminated w] is true when the last [solve] counted an eliminated root. *)
