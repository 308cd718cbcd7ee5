(** The depths a shape's intersection routine accepts. *)

type t = {
  near : float;  (** roots at (sphere: or below) this depth are rejected: DEPTH_TOLERANCE, 1e-6 *)
  far : float;  (** roots beyond this depth are rejected: MAX_DISTANCE, 1e7 *)
  tangent : float;
      (** a sphere is missed when the squared half-chord is at most this (1e-10), and behind the
          ray when its centre's projection is below it *)
  close : float;
      (** a box keeps the side it found for a slab crossing this close to it, unless the ray is
          steeper towards the new side: CLOSE_TOLERANCE, 1e-6 (§15.1) *)
}

val pov : t
(** [pov] is POV-Ray's fixed limits (§2.1). *)

val robust : t
(** [robust] is the robust mode's: every positive depth, no horizon, tangent rays graze. *)
