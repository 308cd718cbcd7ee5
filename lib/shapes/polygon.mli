(** The polygon (docs/povray-rules.md §15.7; POV-Ray's [shape/polygon.cpp], [parse.cpp: Parse_Polygon]):
    one or more closed outlines in a plane, filled by the even-odd rule. It is flat and has no
    inside: Inside is always false and [inverse] does nothing, so in an intersection it keeps only
    its own hits inside the other members and hides theirs. The points live in the polygon's own
    (u, v) plane, which its transform maps to world space. *)

type t = {
  tr : Transform.t;  (** polygon space (the points in z = 0) to world: the frame, then every modifier *)
  points : float array;  (** the points in polygon space, u and v of each *)
  degenerate : bool;  (** collinear or not coplanar: POV-Ray never hits it *)
}

val close : Vec.t array -> Vec.t array * bool
(** [close points] is the outline as Parse_Polygon leaves it: a point within EPSILON (per
    coordinate) of the current sub-polygon's first point is snapped onto it and ends that
    sub-polygon, the next point starting another; when the last point did not end one, the first
    point of the last sub-polygon is appended. The flag says whether it was appended (POV-Ray's
    "Polygon not closed" warning). *)

val make : Vec.t array -> t
(** [make points] is Compute_Polygon on the closed outline [points] (at least 3): the frame u, v,
    w = u × v from the first point and the first two later ones that span a plane, and every point
    projected onto (u, v). *)

val transform : t -> Transform.t -> t
(** [transform p tr] is [p] moved by [tr], composed into its transform (Polygon::Transform). *)

val intersect : Stats.t -> Limits.t -> t -> Vec.t -> Vec.t -> float array -> int
(** [intersect stats lim p o d out] writes the world depth of the ray's crossing with [p] into
    [out] and returns 1, or returns 0: the ray from [o] along the unit [d] is brought into polygon
    space with its direction renormalised, its crossing with z = 0 taken at 1e-8 ≤ s ≤ 1e7 in those
    units (every positive s in the robust mode, whose [lim.near] is 0), tested by the even-odd rule
    and divided by the direction's length. Counts the test (not for a degenerate polygon) and a
    hit. Allocates nothing. *)

val normal : t -> Vec.t -> Vec.t
(** [normal p _] is the unit normal (0,0,1) of polygon space mapped by the inverse transpose,
    the same everywhere. *)

val inside : t -> Vec.t -> bool
(** [inside p q] is false: a polygon has no inside. *)

val bounds : t -> float array option
(** [bounds p] is the box of the points mapped to world space (min x, y, z, max x, y, z), thickened
    by 1e-3 on each side along an axis thinner than that; None for a degenerate polygon. *)

val pov_box : t -> float array
(** [pov_box p] is POV-Ray's box of [p] (Polygon::Compute_BBox, from its whole transform): the
    points' extent as lower corner and lengths in single precision, an axis shorter than
    SMALL_TOLERANCE (1e-3) widened by it on each side; [[||]] for a degenerate polygon. *)

val magnitude : t -> float
(** [magnitude p] is the largest coordinate magnitude of its box (0 when degenerate). *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w p o d lo] is the crossing's depth if at least [lo], else infinity. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w p id o d lo n] pushes the crossing, if any, as a hit of the member [id]. *)

val traits : Traits.t
(** [traits] is its kind's traits: [inverse] does nothing to it (Polygon::Invert). *)
