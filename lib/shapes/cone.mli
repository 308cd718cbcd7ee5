(** The cylinder and the cone (docs/povray-rules.md §15.2, §15.3) in their canonical space, placed by a
    transform: the cylinder x² + y² ≤ 1, 0 ≤ z ≤ 1, the cone x² + y² ≤ z², dist ≤ z ≤ 1. A hit's
    part is 1 the base (small end, z = dist), 2 the cap (z = 1), 3 the side. *)

type t = {
  ctr : Transform.t;  (** canonical space to world *)
  dist : float;  (** a cone's small end at z = [dist] (0 for a cylinder) *)
  cyl : bool;  (** the canonical cylinder instead of the cone *)
  closed : bool;  (** the end caps are surfaces *)
}

val base_hit : int
(** [base_hit] is the part of a hit on the base (POV-Ray's BASE_HIT). *)

val cap_hit : int
(** [cap_hit] is the part of a hit on the cap (CAP_HIT). *)

val side_hit : int
(** [side_hit] is the part of a hit on the side (SIDE_HIT). *)

val crossings : Scratch.t -> t -> Vec.t -> Vec.t -> float array -> int
(** [crossings w c o d out] lists every crossing of the ray from [o] along the unit [d] within the
    shape's own limits (canonical depths 1e-9 < s < 1e7, divided by the length of the canonical
    direction; Cone::Intersect), in POV-Ray's order: the side's roots, then the cap (z = 1), then
    the base (z = dist). Crossing [i] is written as the world depth [out.(2i)] and the part
    [out.(2i+1)]; the result is how many (at most 4, so [out] needs 8 floats). No minimum depth is
    applied. The test and a hit are counted. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w c o d lo] is the nearest crossing at least [lo], its part left in [w.part]; of equal
    depths the last listed wins. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w c id o d lo n] pushes the crossings at least [lo], in their order, with their parts
    (Cone::All_Intersections); it is the new count. *)

val normal : t -> int -> Vec.t -> Vec.t
(** [normal c part p] is Cone::Normal: in canonical space the side's (x, y, 0) for a cylinder and
    (x, y, −z) for a cone, the ends ±z; then by the inverse transpose, normalised (§14.6). *)

val inside : t -> Vec.t -> bool
(** [inside c p] is Cone::Inside: closed shapes shrunk by EPSILON, open ones grown by it (an open
    cylinder still has a solid inside). *)

val bounds : t -> float array
(** [bounds c] is the box of the canonical box's mapped corners. *)

val pov_box : t -> float array
(** [pov_box c] is Cone::Compute_BBox: Make_BBox(−1, −1, dist, 2, 2, 1 − dist) through the transform. *)

val traits : Traits.t
(** [traits] is its kind's traits (cylinders and cones): [Traits.default]. *)
