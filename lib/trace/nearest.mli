(** The nearest hit along a ray (docs/povray-rules.md §2.1), with POV-Ray's tie rules: unbounded objects
    (planes, infinite quadrics) one by one, the others through the bounding hierarchy, and of equal (or, where POV-Ray's bounding
    tree decides it, nearly equal) depths the object POV-Ray meets first. *)

val search : Context.t -> Compiled.group -> Vec.t -> Vec.t -> float -> float -> int
(** [search ctx g o d lo hi] is the id of the nearest object of [g] hit along the unit direction
    [d] from [o] at a depth in [lo, hi), or −1 (a CSG reports its member hit). Its depth is left in
    [ctx.reach.depth], the part hit in [ctx.found.part], and what its shape reported of the crossing
    (a julia fractal, a bicubic patch, a parametric surface) in [ctx.crossing] when
    [ctx.found.reported]. Of equal depths the one POV-Ray meets
    first wins; in the robust mode, of depths within rounding of each other the one written first. *)

val tie_tolerance : Vec.t -> float -> float
(** [tie_tolerance o t] is the robust mode's tie width at depth [t] from [o]: depths this close
    (relative to the ray's origin and length) differ only by rounding, as on coplanar surfaces. *)
