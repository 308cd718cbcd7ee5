(** The crossings of the spline shapes (prism, lathe, sor), gathered in the scratch's [curve] room
    in the order POV-Ray pushes them, and the part code of a hit on a spline segment. POV-Ray's
    normal of a prism or lathe reads the segment and the curve parameter w its intersection
    found; here the part carries both: 1 and 2 are the base and the cap, and a spline hit is
    [3 + j + (segments + 3)·q] with q = w·2^k rounded, so that w comes back within 2^−41 (far below
    what a normal's 8-bit shading can show). *)

(** The constants of the spline shapes, POV-Ray's. *)
module Limits : sig
  val epsilon : float
  (** [epsilon] is EPSILON ([Precision.epsilon]). *)

  val max_distance : float
  (** [max_distance] is MAX_DISTANCE (1e7), the farthest depth kept. *)

  val depth_tolerance : float
  (** [depth_tolerance] is DEPTH_TOLERANCE (1e-4), the nearest depth kept. *)

  val bound_huge : float
  (** [bound_huge] is BOUND_HUGE (2e10). *)

  val cmin : float -> float -> float
  (** [cmin a b] is std::min: [a] unless [b] is strictly below it. *)

  val cmax : float -> float -> float
  (** [cmax a b] is std::max: [a] unless [b] is strictly above it. *)
end

val near_limit : Scratch.t -> float
(** [near_limit w] is the nearest depth a crossing may have: [Limits.depth_tolerance], or 0 in
    the robust mode. *)

val revolution_box : radius2:float -> height1:float -> height2:float -> float array
(** [revolution_box ~radius2 ~height1 ~height2] is the box (min corner, max corner) of a shape
    of revolution in its own space: −[radius2] … [radius2] in x and z, [height1] … [height2] in y. *)

val revolution_pov_box : Transform.t -> radius2:float -> height1:float -> height2:float -> float array
(** [revolution_pov_box tr ~radius2 ~height1 ~height2] is Lathe::Compute_BBox and
    Sor::Compute_BBox: Make_BBox of that box (corner and lengths in single precision), mapped by
    [tr] ([Pov_box.mapped]). *)

val add : Scratch.t -> int -> float -> int -> int
(** [add w k t part] appends the crossing at world depth [t] on [part] after the first [k]; it is
    [k + 1]. *)

val nearest : Scratch.t -> int -> float -> float
(** [nearest w k lo] is the nearest of the [k] crossings at least [lo], its part left in
    [w.part], or infinity; of equal depths the last pushed wins (POV-Ray's intersection stack). *)

val push : Scratch.t -> int -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [push w k id o d lo n] pushes the [k] crossings at least [lo] as hits of the member [id] after
    the first [n] CSG hits; it is the new count. *)

val spline_part : segments:int -> int -> float -> int
(** [spline_part ~segments j w] is the part of a hit on segment [j] (of [segments]) at the curve
    parameter [w] ∈ [0, 1]. *)

val segment : segments:int -> int -> int
(** [segment ~segments part] is the segment of a spline part. *)

val parameter : segments:int -> int -> float
(** [parameter ~segments part] is the curve parameter of a spline part (to 2^−41 or better). *)

val box_admits : float array -> Vec.t -> Vec.t -> bool
(** [box_admits b o d] is POV-Ray's per-object box test before a top-level object is tried
    (Trace::FindIntersection, ObjectBase::Intersect_BBox): the ray from [o] along [d] against
    the single-precision box [b] ([Pov_box] layout; [[||]] admits every ray), in single
    precision, leaving beyond MIN_ISECT_DEPTH (1e-4). A ray lying in a face plane of the box with
    a zero direction component fails it (0·∞ is NaN). *)
