(** The nearest hit along a ray (docs/povray-rules.md §2.1), with POV-Ray's tie rules: unbounded objects
    (planes, infinite quadrics) one by one, the others through the bounding hierarchy, and of equal (or, where POV-Ray's bounding
    tree decides it, nearly equal) depths the object POV-Ray meets first. *)

type found
(** What a search found: the nearest object hit, the part of it hit, its depth and what its shape
    reported of the crossing. It is the worker's own record, read through the functions below
    until the worker's next search (a search allocates nothing). *)

val search : Context.t -> Ray.kind -> Compiled.group -> Vec.t -> Vec.t -> float -> float -> found
(** [search ctx kind g o d lo hi] is the nearest object of [g] hit by a ray of the kind [kind]
    along the unit direction [d] from [o] at a depth in [lo, hi) (a CSG gives its member hit). Of
    equal depths the one POV-Ray meets first wins; in the robust mode, of depths within rounding
    of each other the one written first. The shapes are told the ray's kind (POV-Ray's
    Ray::IsShadowTestRay): an isosurface keeps no cache of a shadow ray's search. *)

val hit : found -> bool
(** [hit f] is whether the search found an object. *)

val id : found -> int
(** [id f] is the id of the object found (its index in the scene's objects), or −1. *)

val part : found -> int
(** [part f] is the part of the object hit (a mesh's face, a box's side …), or −1. *)

val depth : found -> float
(** [depth f] is the depth of the hit along the ray. *)

val crossing : found -> Crossing.t
(** [crossing f] is what the shape hit reported of the crossing (a julia fractal's point and
    normal, a bicubic patch's normal and (u, v), a parametric surface's (u, v)), a copy that the
    next search leaves as it is; {!Crossing.none} for the other shapes. *)

val shape_depth : Context.t -> Ray.kind -> Compiled.shape -> Vec.t -> Vec.t -> float -> float
(** [shape_depth ctx kind shape o d lo] is {!Shape.depth} of [shape] for a ray of the kind [kind]
    (the shadow cache's test of its object, in the robust mode). *)

val cached_depth : Context.t -> Ray.kind -> Compiled.shape -> Vec.t -> Vec.t -> float -> float -> float
(** [cached_depth ctx kind shape o d lo hi] is {!Shape.cached_depth} of [shape] for a ray of the
    kind [kind] (the shadow cache's test of its object). *)

val tie_tolerance : Vec.t -> float -> float
(** [tie_tolerance o t] is the robust mode's tie width at depth [t] from [o]: depths this close
    (relative to the ray's origin and length) differ only by rounding, as on coplanar surfaces. *)
