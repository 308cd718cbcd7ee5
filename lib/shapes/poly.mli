(** The polynomial surfaces [poly], [cubic] and [quartic] (POV-Ray's shape/poly.cpp, Parse_Poly):
    the surface where Σ c·x^i·y^j·z^k = 0 in the poly's own space, solid where that sum is below
    INSIDE_TOLERANCE (1e-4). The coefficients are in POV-Ray's term order: the power of x from
    the order down to 0, within it the power of y, then of z, each descending. Every modifier
    composes into the transform ([Trans]); rays are brought into poly space with the direction
    made unit, and depths are returned in world units. A poly is unbounded (POV-Ray's box is
    BOUND_HUGE wide, an infinite object). *)

type t = {
  order : int;  (** 2 … 35 *)
  coeffs : float array;  (** [term_count order] coefficients *)
  sturm : bool;  (** solve cubics and quartics with Sturm sequences (above 4 always) *)
  tr : Transform.t;  (** poly space to world *)
}

val max_order : int
(** 35: POV-Ray's MAX_ORDER, the highest order a poly may have. *)

val term_count : int -> int
(** [term_count n] is the number of coefficients of a polynomial of order [n] in three variables,
    (n+1)(n+2)(n+3)/6 (POV-Ray's term_counts). *)

val index : int -> int -> int -> int -> int option
(** [index order x y z] is where the coefficient of x^x·y^y·z^z goes among the coefficients of a
    poly of [order] (Poly::Set_Coeff, for [polynomial]'s [xyz(x, y, z): value]); None when a power
    is negative or their sum exceeds [order]. *)

val make : order:int -> float array -> t
(** [make ~order c] is the poly of [order] with the coefficients [c], without Sturm, in place. *)

val depth_tolerance : float
(** 1e-4: roots at or below this depth in poly space (DEPTH_TOLERANCE) are no hit. *)

val crossings : Scratch.t -> t -> Vec.t -> Vec.t -> int
(** [crossings w p o d] is Poly::All_Intersections of the ray from [o] along the unit [d]: the
    roots (order 2 by intersect_quadratic, above by the expanded polynomial in t and
    Solve_Polynomial with ROOT_TOLERANCE, when its degree is above 1) beyond DEPTH_TOLERANCE in
    poly space and distinct from every earlier root, in the solver's order; their world depths and
    world points (the poly-space point mapped back by the transform) are left in the scratch's
    [poly_room]. Returns their number; counts "Quartic/Poly" and "Roots tested … eliminated". *)

val crossing : Scratch.t -> int -> float
(** [crossing w i] is the world depth of crossing [i] of the last [crossings] (or [depth], [hits]). *)

val hit_point : Scratch.t -> t -> Vec.t -> Vec.t -> float -> Vec.t
(** [hit_point w p o d depth] is the world point POV-Ray shades for the crossing at the world
    [depth] along the ray: the poly-space point mapped back by the transform, which can differ in
    its last bits from [o + depth·d] (the crossings found again, not counted); [o + depth·d] when
    no crossing is at [depth]. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w p o d lo] is the nearest of those depths at least [lo], or infinity. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w p id o d lo n] pushes the crossings at least [lo], with POV-Ray's world points, as
    hits of the member [id]; it is the new count. *)

val value : t -> Vec.t -> float
(** [value p q] is the polynomial at the poly-space point [q] (Poly::inside: the non-zero terms
    summed in term order). *)

val inside : t -> Vec.t -> bool
(** [inside p pt] is Poly::Inside of the world point [pt], before any inversion: the value below
    INSIDE_TOLERANCE. *)

val gradient : t -> Vec.t -> Vec.t
(** [gradient p q] is the polynomial's gradient at the poly-space point [q]: normal1's written-out
    partial derivatives for orders up to 4, normal0's term by term sum above. *)

val normal : t -> Vec.t -> Vec.t
(** [normal p pt] is Poly::Normal at the world point [pt]: the gradient by the inverse transpose,
    times the reciprocal of its length; <1, 0, 0> where the gradient vanishes. *)

val traits : Traits.t
(** [traits] is its kind's traits (poly, cubic, quartic): its box test is free, and [sturm] takes
    an optional boolean. *)
