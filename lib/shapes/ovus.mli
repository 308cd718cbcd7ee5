(** The ovus (POV-Ray 3.7's shape/ovus.cpp): in its own space a sphere of radius [bottom] at the
    origin, a sphere of radius [top] at height [bottom], and the inner part of a spindle torus
    about the y axis joining them between the heights [bvert] and [tvert]; mapped to the world by
    its transform. *)

type t = {
  bottom : float;  (** BottomRadius, as written *)
  top : float;  (** TopRadius, as written *)
  hpos : float;  (** HorizontalPosition: the torus's core-circle radius *)
  vpos : float;  (** VerticalPosition: the torus's height *)
  bvert : float;  (** BottomVertical: where the joint meets the bottom sphere *)
  tvert : float;  (** TopVertical: where it meets the top sphere *)
  crad : float;  (** ConnectingRadius: the torus's tube radius *)
  sturm : bool;  (** solve the joint's quartic with Sturm sequences *)
  tr : Transform.t;  (** ovus space to world *)
}

val set_up : float -> float -> t option
(** [set_up bottom top] is Parse_Ovus's pre-computation for radii already checked to be positive;
    None when [top] ≥ 2·[bottom], where POV-Ray puts a sphere of radius [top] at height [bottom]
    in its place. *)

val transform : t -> Transform.t -> t
(** [transform v m] is [v] moved by [m] (Ovus::Transform composes it into Trans). *)

val intersect : Scratch.t -> t -> Vec.t -> Vec.t -> float array -> int
(** [intersect w v o d out] is Ovus::All_Intersections of the world ray from [o] along [d]: the
    (world depth, part) pairs in POV-Ray's push order written into [out] (room for 12), their
    number returned. Parts: 1 the bottom sphere, 2 the top one, 3 the joint. Only depths above
    EPSILON in ovus space are kept (there is no other limit). "Roots tested" and "eliminated"
    are counted for the joint's quartic. *)

val normal : t -> int -> Vec.t -> Vec.t
(** [normal v part p] is the normal POV-Ray stores with a hit on [part] at the world point [p]:
    the sphere's radius vector over its radius, or the joint's normalised radius vector from its
    tube's centre, by the inverse transpose, normalised. *)

val inside : t -> Vec.t -> bool
(** [inside v p] is Ovus::Inside of the world point [p] (not inverted), the surface excluded. *)

val bounds : t -> float array
(** [bounds v] is the box of the corners of Compute_BBox's box mapped by the transform. *)

val pov_box : t -> float array
(** [pov_box v] is Ovus::Compute_BBox: the widest of the joint (ConnectingRadius −
    HorizontalPosition) and the two radii across, −bottom to bottom + top in y, through the
    transform. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w v o d lo] is the nearest hit at least [lo], its part left in [w.part], or infinity;
    counted ("Ovus"). *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w v id o d lo n] pushes the hits at least [lo], with their parts, in POV-Ray's order as
    hits of the member [id]; it is the new count. *)

val uv : t -> Vec.t -> Vec.t
(** [uv v p] is Ovus::CalcUV at the world point [p]: the angles of a sphere about the point
    [top]/2 up the axis, as (u, v, 0). *)

val traits : Traits.t
(** [traits] is its kind's traits: [sturm] takes an optional boolean. *)
