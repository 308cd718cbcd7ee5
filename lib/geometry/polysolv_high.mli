(** POV-Ray's [Solve_Polynomial] up to degree 6 (POVRAY-3.7 §15.6): degrees 5 and 6 by its Sturm
    sequences ([polysolve]), the only method POV-Ray has for them; a polynomial whose real degree
    is 4 or less (after small leading coefficients are dropped) is handed to [Polysolv.solve] as
    it is, so its roots are [Polysolv]'s to the last bit. Nothing is allocated per call. *)

type work
(** Room for one solve at a time. *)

val create : unit -> work
(** [create ()] is fresh work room, for one render worker. *)

val solve : work -> float array -> int -> sturm:bool -> eps:float -> float array -> int
(** [solve w c n ~sturm ~eps roots] solves [c.(0)·xⁿ + … + c.(n) = 0] for [n] ≤ 6, writing its roots
    into [roots] (room for [n]) and returning their number. Leading coefficients below 1e-10 in
    magnitude lower the degree; at degree 5 or 6 only the roots in [0, 1e7] are found (Sturm),
    whatever [sturm] says. Raises [Invalid_argument] for [n] > 6. *)

val eliminated : work -> bool
(** [eliminated w] is true when the last [solve] with [w] counted a root at 0 as eliminated. *)
