(** The lathe (POV-Ray's [shape/lathe.cpp], [Parse_Lathe]): a 2-D spline of (radius, height)
    points rotated about the Y axis of its own space. A ray meets a segment where a polynomial in
    the curve parameter vanishes: degree 2 (linear spline), 4 (quadratic) or 6 (cubic and Bezier,
    solved by [Polysolv]'s Sturm sequences). No caps. Placed by its transform, the ray
    renormalised in lathe space; depths in world units. *)

type spline = Prism.spline

type segment = { ax : float; ay : float; bx : float; by : float; cx : float; cy : float; dx : float; dy : float }
(** radius and height of the segment as cubics A·w³ + B·w² + C·w + D, w ∈ [0, 1] *)

type t = {
  spline : spline;
  segs : segment array;
  bcyl : Bcyl.t;  (** the segments' bounding cylinders *)
  height1 : float;
  height2 : float;
  radius1 : float;
  radius2 : float;  (** the overall bounding cylinder *)
  sturm : bool;
  tr : Transform.t;  (** lathe space to world *)
  pbox : float array;  (** [pov_box] as it stands, kept for the per-object box test *)
}

val segment_count : spline -> int -> int
(** [segment_count s n] is the number of segments of n points: n − 1, n − 2, n − 3, n / 4. *)

val make : spline:spline -> sturm:bool -> (float * float) array -> t
(** [make ~spline ~sturm pts] is Compute_Lathe of the points, with the identity transform. *)

val transform : t -> Transform.t -> t
(** [transform t m] composes [m] into the transform (Lathe::Transform). *)

val crossings : Scratch.t -> t -> all:bool -> Vec.t -> Vec.t -> int
(** [crossings w t ~all o d] writes the crossings of the ray from [o] along the unit [d] into the
    curve room of [w] in POV-Ray's order (segments by bounding-cylinder entry, each one's roots
    from the last) and returns their number: world depths beyond 1e-4 (none in the robust mode)
    and below 1e7. Unless [all], the segments stop at the first entered beyond the nearest hit.
    The statistics are counted. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w t o d lo] is the nearest crossing at least [lo] (its part in [w.part]), or infinity;
    only when the ray passes [Curve_hits.box_admits] of [t.pbox] (not in the robust mode). *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w t id o d lo n] pushes every crossing at least [lo] as a hit of the member [id]. *)

val inside : t -> Vec.t -> bool
(** [inside t p] is Lathe::Inside (before inversion): the crossings of the segments, towards
    growing radius at the point's height, counted; odd is inside. *)

val normal : t -> int -> Vec.t -> Vec.t
(** [normal t part p] is the unit normal at [p]: the curve's derivative at the hit's parameter
    rotated about Y (⟨0, 1, 0⟩ on the axis); mapped by the inverse transpose. *)

val uv : t -> int -> Vec.t -> Vec.t
(** [uv t part p] is Lathe::UVCoord: u the angle about Y, v = (w + segment)/segments, at most 1. *)

val bounds : t -> float array
(** [bounds t] is the box of the mapped corners of the cylinder's box. *)

val pov_box : t -> float array
(** [pov_box t] is Lathe::Compute_BBox: Make_BBox of −R2 … R2, height1 … height2, mapped. *)

val traits : Traits.t
(** [traits] is its kind's traits: [sturm] alone turns Sturm sequences on. *)
