(** The surface of revolution (POV-Ray's [shape/sor.cpp], [Parse_Sor]): about the Y axis of its own
    space, the squared radius in segment i a cubic A·y³ + B·y² + C·y + D of the height through the
    points i+1 and i+2 (radius, height) with the slopes that points i and i+3 give; capped by
    discs at the lowest and highest height unless [open]. Placed by its transform, the ray
    renormalised in sor space; depths in world units. *)

type segment = { a : float; b : float; c : float; d : float }  (** radius² = A·y³ + B·y² + C·y + D *)

type t = {
  segs : segment array;
  bcyl : Bcyl.t;  (** the segments' bounding cylinders *)
  height1 : float;
  height2 : float;
  radius1 : float;
  radius2 : float;  (** the overall bounding cylinder *)
  base_radius2 : float;
  cap_radius2 : float;  (** the squared radii of the base and cap discs (0 when negative) *)
  closed : bool;
  sturm : bool;
  tr : Transform.t;  (** sor space to world *)
  pbox : float array;  (** [pov_box] as it stands, kept for the per-object box test *)
}

val make : closed:bool -> sturm:bool -> (float * float) array -> (t, string) result
(** [make ~closed ~sturm pts] is Compute_Sor of the n ≥ 4 points (n − 3 segments), with the
    identity transform: each segment's coefficients from MInvers of its 4×4 system, those below
    1e-10 set to 0, its radius range from the points and the derivative's roots; [Error] with
    POV-Ray's message for two points at the same height ("Incorrect point in surface of
    revolution."). *)

val transform : t -> Transform.t -> t
(** [transform t m] composes [m] into the transform (Sor::Transform). *)

val crossings : Scratch.t -> t -> all:bool -> Vec.t -> Vec.t -> int
(** [crossings w t ~all o d] writes the crossings of the ray from [o] along the unit [d] into the
    curve room of [w] in POV-Ray's order (base, cap, then the segments by bounding-cylinder entry,
    each one's roots from the last) and returns their number: world depths beyond 1e-4 (none in
    the robust mode) and below 1e7. Unless [all] (a CSG member), the segments stop at the first
    one entered beyond the nearest hit so far, as for a top-level object. Parts: 1 base, 2 cap,
    3 + segment. The statistics are counted. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w t o d lo] is the nearest crossing at least [lo] (its part in [w.part]), or infinity;
    only when the ray passes [Curve_hits.box_admits] of [t.pbox] (not in the robust mode). *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w t id o d lo n] pushes every crossing at least [lo] as a hit of the member [id]. *)

val inside : t -> Vec.t -> bool
(** [inside t p] is Sor::Inside (before inversion): within the heights and the outer radius, and
    r² at most the first segment's radius² at that height whose height range holds it. *)

val normal : t -> int -> Vec.t -> Vec.t
(** [normal t part p] is the unit normal at [p]: −y on the base, +y on the cap, (x, −½·d(r²)/dy, z)
    on a segment; mapped by the inverse transpose. *)

val angle : Vec.t -> float
(** [angle q] is the angle of [q] about Y from +x, as a fraction of a turn (0 on the axis). *)

val uv : t -> int -> Vec.t -> Vec.t
(** [uv t part p] is Sor::UVCoord: u the angle, v along the segments (1/n per segment), or on the
    base and cap from the radius. *)

val bounds : t -> float array
(** [bounds t] is the box of the mapped corners of the cylinder's box. *)

val pov_box : t -> float array
(** [pov_box t] is Sor::Compute_BBox: Make_BBox of −R2 … R2, height1 … height2, mapped by the
    transform. *)

val traits : Traits.t
(** [traits] is its kind's traits: [sturm] alone turns Sturm sequences on. *)
