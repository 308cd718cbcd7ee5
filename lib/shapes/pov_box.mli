(** POV-Ray's bounding box of an object as it stores it: the lower corner and the lengths, each
    rounded to single precision, [[| llx; lly; llz; lx; ly; lz |]]; [[||]] for an unbounded object
    (a plane, an infinite quadric). POV-Ray's bounding tree meets objects in the order the ray enters these boxes,
    which decides exact depth ties (§2.1), and it tests a CSG's box before the CSG (§15.8). *)

val of_min_max : float array -> float array -> float array
(** [of_min_max lo hi] is the box from the corners [lo] and [hi] (3 floats each), as POV-Ray's
    Make_BBox_from_min_max rounds them. *)

val volume : float array -> float
(** [volume b] is BOUNDS_VOLUME: the product of the box's lengths, in single precision. *)

val infinite : float array -> bool
(** [infinite b] is whether POV-Ray flags an object with the box [b] infinite (Post_Process): an
    unbounded box, or a volume above BOUND_HUGE (2e10), so a sphere of radius 1500 is infinite.
    POV-Ray keeps infinite objects out of its bounding tree and tests them first, without their box. *)

val mapped : Transform.t -> float array -> float array
(** [mapped tr b] is the box of the corners of the box [b] mapped by [tr] (Recompute_BBox). *)

val entry : float array -> Vec.t -> Vec.t -> float
(** [entry b o d] is where the ray from [o] along [d] enters the box [b] (Check_And_Enqueue, with
    the ray as its Rayinfo holds it: origin and reciprocal direction in single precision, the slab
    arithmetic in single precision too), or infinity when it misses the box. *)

type ray_info
(** A ray as Check_And_Enqueue's Rayinfo holds it, set once for the many boxes it is tested
    against. *)

val ray_info : unit -> ray_info
(** [ray_info ()] is a fresh record, to be set by [set_ray]. *)

val set_ray : ray_info -> Vec.t -> Vec.t -> unit
(** [set_ray i o d] makes [i] the ray from [o] along [d]. *)

val entry_from : ray_info -> float array -> float
(** [entry_from i b] is [entry b o d] for the ray [i] was set to, the same float. *)

val contains : float array -> Vec.t -> bool
(** [contains b p] is Inside_BBox: whether [p] is in the box [b], faces included; an unbounded
    object's box ([[||]]) holds every point. *)

val met : float array -> Vec.t -> Vec.t -> within:float -> bool
(** [met b o d ~within] is ObjectBase::Intersect_BBox as FindIntersection asks it of one object
    (a cached shadow blocker, a trace() target): whether the ray from [o] along [d] crosses the
    box [b] between MIN_ISECT_DEPTH and [within], in single precision; an unbounded box always. *)
