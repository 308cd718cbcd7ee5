(** The superellipsoid (POV-Ray 3.7's shape/super.cpp): the surface
    [(|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1] in its own space, within the box ±1, mapped to
    the world by its transform. Its intersection is POV-Ray's own root search, not a polynomial
    solver: the ray is cut at the planes that split the shape into monotonic pieces, and each
    piece is searched by secant and bisection steps. *)

type t = {
  ex : float;  (** Power[X] = 2/e: the exponent of x and y *)
  ey : float;  (** Power[Y] = e/n (stored by POV-Ray, unused by its formulas) *)
  ez : float;  (** Power[Z] = 2/n: the exponent of z, and of the xy term *)
  tr : Transform.t;  (** superellipsoid space to world *)
}

val make : float -> float -> t
(** [make e n] is [superellipsoid { <e, n> }] as Parse_Superellipsoid sets it up (identity
    transform). *)

val transform : t -> Transform.t -> t
(** [transform s m] is [s] moved by [m] (Superellipsoid::Transform composes it into Trans). *)

val power : float -> float -> float
(** [power x e] is POV-Ray's [power]: [x^e], multiplied out for the integer powers 0 to 6. *)

val value : t -> float -> float -> float -> float
(** [value s x y z] is evaluate_superellipsoid at the superellipsoid-space point: below 0
    inside, 0 on the surface. *)

val depth_tolerance : float
(** 1e-4: hits at or below this world depth are dropped (DEPTH_TOLERANCE). *)

val intersect : t -> near:float -> all:bool -> Vec.t -> Vec.t -> float array -> int
(** [intersect s ~near ~all o d out] is Superellipsoid::Intersect of the world ray from [o] along
    [d]: the world depths in ([near], 1e7) written into [out] (room for 11) in the order found,
    their number returned. With [all] false it stops at the first, as POV-Ray does for a shape
    that is not a CSG member. Statistics are not counted. *)

val inside : t -> Vec.t -> bool
(** [inside s p] is Superellipsoid::Inside of the world point [p] (not inverted): its value below
    EPSILON (1e-10). *)

val normal : t -> Vec.t -> Vec.t
(** [normal s p] is Superellipsoid::Normal at the world point [p]: the gradient's direction in
    superellipsoid space as POV-Ray writes it, by the inverse transpose, normalised. *)

val bounds : t -> float array
(** [bounds s] is the box of the corners ±1.0001 mapped by the transform. *)

val pov_box : t -> float array
(** [pov_box s] is Superellipsoid::Compute_BBox: Make_BBox(−1.0001, …, 2.0002, …) through the
    transform (Recompute_BBox). *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w s o d lo] is the first hit found (the only one a shape alone pushes) when it is at
    least [lo], else infinity; counted ("Superellipsoid"). *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w s id o d lo n] pushes every hit at least [lo], in the order found, as hits of the
    member [id] (All_Superellipsoid_Intersections of a CSG member); it is the new count. *)

val traits : Traits.t
(** [traits] is its kind's traits: [Traits.default]. *)
