(** The robust mode's secondary-ray origins. A computed hit point is off the true surface by a few
    rounding errors of the coordinates it was computed from; a secondary ray leaves from the point
    moved off the surface, to the side the ray goes, by a bound on that error, and then accepts
    every positive depth. Every length here is relative to the coordinates, so the decision is the
    same whatever the size and position of the scene. In POV-Ray's mode a secondary ray leaves from
    the hit point itself. *)

val error_bound : shift:float -> Vec.t -> Vec.t -> float -> float
(** [error_bound ~shift o p mag] bounds the error of the hit point [p] of a ray from [o] on a shape
    whose coordinates reach [mag]: 256 units in the last place of the largest coordinate involved,
    and 4 of [shift], how far the whole scene was moved (its coordinates' rounding on the way). *)

val origin : Context.t -> Vec.t -> Vec.t -> float -> Vec.t -> Vec.t
(** [origin ctx p ng e dir] is where a ray in direction [dir] leaves the surface at [p]: [p] itself
    in POV-Ray's mode; in the robust mode, [p] moved by [e] along the geometric normal [ng] to the
    side [dir] goes. *)
