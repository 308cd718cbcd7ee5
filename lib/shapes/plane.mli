(** The plane (docs/povray-rules.md §2.3): the points P with N·P = offset, and the plane mapped by a
    transform (§14.5 (a)). Planes are unbounded. *)

type t = { nx : float; ny : float; nz : float; dist : float }
(** The unit normal and POV-Ray's [Distance] = −offset. *)

type moved = { pl : t; ptr : Transform.t; pnormal : Vec.t }
(** [pl] mapped by [ptr]; [pnormal] is its world normal, the same at every point. *)

val make : Vec.t -> float -> t
(** [make normal offset] is the plane. *)

val moved : Vec.t -> float -> Transform.t -> moved
(** [moved normal offset tr] is the plane mapped by [tr], its normal by the inverse transpose,
    normalised (§14.6). *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w p o d lo] is the depth within the limits and at least [lo] where the ray meets [p], or
    infinity (none for a ray closer to parallel than EPSILON). *)

val moved_depth : Scratch.t -> moved -> Vec.t -> Vec.t -> float -> float
(** [moved_depth] is [depth] in object space, the direction NOT renormalised, so the depth is the
    world depth and the limits apply to it. *)

val inside : t -> Vec.t -> bool
(** [inside p q] is N·Q − offset < EPSILON: the half-space behind the normal. *)

val moved_inside : moved -> Vec.t -> bool
(** [moved_inside] is [inside] in object space. *)

val magnitude : t -> float
(** [magnitude p] is the distance of the plane's nearest point to the origin. *)

val moved_magnitude : moved -> float
(** [moved_magnitude] is the largest coordinate of that point, mapped. *)

val traits : Traits.t
(** [traits] is its kind's traits: tested at once, its box test free, and [inverse] turns it over
    (Plane::Invert) instead of setting the flag. *)
