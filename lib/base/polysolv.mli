(** POV-Ray's polynomial solver, [Solve_Polynomial] of its default build (docs/povray-rules.md §15.6), up to
    degree 35 (MAX_ORDER): closed forms for degrees 1–3, Ferrari's quartic, root elimination, the
    [difficult] test and Sturm sequences with modified regula falsi (every degree above 4). Every operation is done in the same
    order as POV-Ray does it, so the roots are the same to the last bit. Nothing is allocated per
    call: the work room comes from a [work] value made once per render worker. *)

type work
(** Room for one solve at a time: the Sturm sequence, the resolvent cubic and its roots. *)

val create : unit -> work
(** [create ()] is fresh work room. A [work] must not be used by two solves at the same time. *)

val solve : work -> float array -> int -> sturm:bool -> eps:float -> float array -> int
(** [solve w c n ~sturm ~eps roots] solves [c.(0)·xⁿ + c.(1)·xⁿ⁻¹ + … + c.(n) = 0] for [n] ≤ 35
    and writes its roots into [roots.(0 …)] (room for [n]), returning their number. Leading
    coefficients below 1e-10 in magnitude lower the degree. With [eps] > 0 a root at 0 is dropped
    when [|c.(n)/c.(n−1)| < eps] (degrees 3 and 4). [sturm] chooses Sturm sequences (only roots in
    [0, 1e7]) over the closed forms for degrees 3 and 4; a quartic with coefficients too far apart
    ([difficult]) always uses them; degrees above 4 always do (with [eps] > 0 a root at 0 there is
    only counted as eliminated: POV-Ray solves the whole polynomial all the same). The roots are in
    POV-Ray's order, not sorted, and may repeat. Raises [Invalid_argument] for [n] > 35. *)

val solve_at : work -> float array -> int -> int -> sturm:bool -> eps:float -> float array -> int -> int
(** [solve_at w c o n ~sturm ~eps roots j] is [solve] of the polynomial whose coefficients start at
    [c.(o)], its roots written from [roots.(j)]. *)

val quadratic : float array -> int -> float array -> int -> int
(** [quadratic x i y j] is POV-Ray's [solve_quadratic] of [x.(i)·t² + x.(i+1)·t + x.(i+2)]: the
    roots written from [y.(j)], their number returned (a discriminant within 1e-10 of 0 gives one
    root). *)

val cubic : float array -> int -> float array -> int -> int
(** [cubic x i y j] is POV-Ray's [solve_cubic] of the cubic whose coefficients start at [x.(i)]
    (trigonometric for three real roots, else one root by Cardano's formula). *)

val quartic : work -> float array -> int -> float array -> int -> int
(** [quartic w x i y j] is POV-Ray's [solve_quartic] (Ferrari's method through the resolvent
    cubic), with its sign slip when a factor's discriminant is exactly 0. *)

val sturm : work -> float array -> int -> int -> float array -> int -> int
(** [sturm w c i n y j] is POV-Ray's [polysolve]: the roots in [0, 1e7] of the degree-[n]
    polynomial whose coefficients start at [c.(i)], isolated by the Sturm sequence and refined by
    modified regula falsi or bisection. *)

val difficult : float array -> int -> bool
(** [difficult c i] is POV-Ray's [difficult_coeffs] test on the quartic starting at [c.(i)]: true
    when some non-zero coefficient is more than 1e12 times smaller than the "biggest" one, which
    is kept with its SIGN (a quirk: a negative biggest coefficient still counts by magnitude in
    the ratio). *)

val eval : float array -> int -> int -> float -> float
(** [eval c i n x] is the degree-[n] polynomial with coefficients from [c.(i)] (highest power
    first) at [x], by Horner's rule. For tests. *)

val eliminated : work -> bool
(** [eliminated w] is true when the last [solve] with [w] dropped a root at 0 (POV-Ray's "Roots
    eliminated" statistic). *)
