(** The sphere sweep (POV-Ray 3.7's shape/sphsweep.cpp): the volume a sphere sweeps along a
    spline through modeling spheres (their centres and radii interpolated together): linear,
    Catmull-Rom ([cubic_spline]) or B-spline. Its segments are polynomials in u ∈ [0, 1]; single
    spheres close them; the hits inside the sweep are dropped (Find_Valid_Points). Without a
    transform the ray is used as it is; a transform starts with the first modifier the modeling
    spheres cannot take (a non-uniform scale, a matrix). *)

type interpolation = Linear | Catmull_rom | B_spline

type t = {
  interpolation : interpolation;
  spheres : (Vec.t * float) array;  (** the modeling spheres (centre, radius), moved by the modifiers POV-Ray applies to them *)
  tolerance : float;  (** Depth_Tolerance: hits at or below this depth are dropped (1e-6 by default) *)
  trans : Transform.t option;  (** POV-Ray's Trans, NULL until a modifier needs it *)
}

type segment = {
  ncoefs : int;  (** 2 (linear) or 4 (cubic) *)
  cc : Vec.t array;  (** Center_Coef: the centre polynomial's coefficients, u⁰ first *)
  rc : float array;  (** Radius_Coef *)
  c0 : Vec.t;  (** the closing sphere at u = 0 … *)
  r0 : float;
  c1 : Vec.t;  (** … and at u = 1 *)
  r1 : float;
  dc0 : Vec.t;  (** Center_Deriv and Radius_Deriv at u = 0 … *)
  dr0 : float;
  dc1 : Vec.t;  (** … and at u = 1 *)
  dr1 : float;
}
(** One segment as SphereSweep::Compute sets it up. *)

type compiled = {
  sweep : t;
  segments : segment array;
  singles : (Vec.t * float) array;  (** the single spheres: each segment's first, and the last one's end *)
  ubits : int;  (** the bits of a part code that hold a segment's u *)
}

val depth_tolerance : float
(** 1e-6, the default [tolerance]. *)

val make : interpolation -> (Vec.t * float) array -> float -> t
(** [make kind spheres tolerance] is the sweep as Parse_Sphere_Sweep reads it (no transform). *)

type op = Translate of Vec.t | Rotate | Scale of Vec.t | Other  (** a modifier, as the sweep tells them apart *)

val move : t -> op -> Transform.t -> t
(** [move s op m] applies the modifier [op], whose transform is [m]: without a transform yet,
    a translation, a rotation or a uniform scale move the modeling spheres (a scale multiplies
    the radii too); any other modifier makes [m] the transform; with one, [m] is composed into
    it. *)

val compile : t -> compiled
(** [compile s] is SphereSweep::Compute: the segments' coefficients (the spline matrices
    applied as POV-Ray does), closing spheres and end derivatives, and the single spheres. *)

val bezier_01 : ?stats:Stats.t -> Polysolv.work -> int -> float array -> float array -> int
(** [bezier_01 w degree coef roots] is POV-Ray's [bezier_01] for degree 6 or 10: 0 when the
    polynomial's Bernstein coefficients over [0, 1] all have one sign, else Solve_Polynomial's
    roots (counted in [stats] when given). *)

val intersect : Scratch.t -> compiled -> Vec.t -> Vec.t -> (float * int * int) array
(** [intersect w c o d] is SphereSweep::All_Intersections of the world ray: the kept hits as
    (world depth, part, exact part), sorted, beyond the tolerance. A part code names the single
    sphere, the segment's closing surface, or the segment and its u, from which [normal] rebuilds
    the normal POV-Ray stored: the part (below 2⁵³, for a CSG's hit list) with u quantised, the
    exact part (a nearest hit's) with u's own bits. "Roots tested" and "eliminated" are
    counted. *)

val normal : compiled -> int -> Vec.t -> Vec.t
(** [normal c part p] is the normal of the hit [part] at the world point [p]: a sphere's
    (P − C)/R, a closing surface's ∓ derivative normalised, a linear side's P − C(u) normalised,
    through the transform (normalised) if there is one. *)

val inside : compiled -> Vec.t -> bool
(** [inside c p] is SphereSweep::Inside (not inverted): some segment has a sphere holding [p],
    i.e. |P − C(u)|² − R(u)² has a root in [0, 1]. *)

val bounds : compiled -> float array
(** [bounds c] is the modeling spheres' box, mapped by the transform if there is one. *)

val pov_box : compiled -> float array
(** [pov_box c] is SphereSweep::Compute_BBox: the modeling spheres' extent (twice their radii for
    Catmull-Rom), then Recompute_BBox through the transform if there is one. *)

val depth : Scratch.t -> compiled -> Vec.t -> Vec.t -> float -> float
(** [depth w c o d lo] is the nearest hit at least [lo], its part left in [w.part], or infinity;
    counted ("Sphere Sweep"). *)

val hits : Scratch.t -> compiled -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w c id o d lo n] pushes the hits at least [lo], sorted, with their parts, as hits of
    the member [id]; it is the new count. *)

val traits : Traits.t
(** [traits] is its kind's traits: [Traits.default]. *)
