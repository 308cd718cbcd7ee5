(** The sphere (POVRAY-3.7 §2.2), and the ellipsoid: a sphere mapped by a transform (§14.5 (b)). *)

type t = { cx : float; cy : float; cz : float; radius : float; r2 : float }
(** Centre, radius as written (the normal is scaled by its reciprocal), radius². *)

type ellipsoid = { sp : t; etr : Transform.t }
(** The object-space sphere [sp] mapped by [etr]. *)

val make : Vec.t -> float -> t
(** [make centre radius] is the sphere. *)

val depth_at : Stats.t -> Limits.t -> float -> float -> float -> float -> Vec.t -> Vec.t -> float -> float
(** [depth_at stats lim cx cy cz r2 o d lo] is the nearer root within [lim] and at least [lo] of the
    ray from [o] along the unit [d] with the sphere of centre (cx, cy, cz) and radius² [r2], or
    infinity; the test (and a hit) is counted. The scene's search calls it straight from a flat
    array of spheres. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w s o d lo] is [depth_at] of [s]. *)

val ellipsoid_depth : Scratch.t -> ellipsoid -> Vec.t -> Vec.t -> float -> float
(** [ellipsoid_depth w e o d lo] is the nearest depth at least [lo] at which the ray meets [e]: in
    object space with the direction renormalised, the roots limited in object units and divided by
    the length of the object-space direction. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w s id o d lo n] pushes both roots within the limits and at least [lo] as hits of the
    member [id] after the first [n] (Sphere::All_Intersections); it is the new count. *)

val ellipsoid_hits : Scratch.t -> ellipsoid -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [ellipsoid_hits] is [hits] for an ellipsoid; the hit points are the object-space points mapped back. *)

val normal : t -> Vec.t -> Vec.t
(** [normal s p] is (P − C)·(1/radius): Sphere::Normal's VInverseScaleEq multiplies by the
    reciprocal, which can differ from a division in the last bit — enough, on a hit point that
    lands on a quilted or other cell boundary a few bounces later, to change a pixel. *)

val ellipsoid_normal : ellipsoid -> Vec.t -> Vec.t
(** [ellipsoid_normal e p] is P′ − C in object space, by the inverse transpose, normalised (§14.6). *)

val inside : t -> Vec.t -> bool
(** [inside s p] is (P − C)² < r². *)

val ellipsoid_inside : ellipsoid -> Vec.t -> bool
(** [ellipsoid_inside e p] is Sphere::Inside in object space: (C − P′)² < r². *)

val bounds : t -> float array
(** [bounds s] is the box of the sphere (min x, y, z, max x, y, z). *)

val ellipsoid_bounds : ellipsoid -> float array
(** [ellipsoid_bounds e] is the box of the object-space box's mapped corners. *)

val pov_box : t -> float array
(** [pov_box s] is POV-Ray's box: the centre minus the radius, and twice the radius (§2.1). *)

val ellipsoid_pov_box : ellipsoid -> float array
(** [ellipsoid_pov_box e] is the sphere's POV-Ray box mapped by the transform. *)

val refine : t -> Vec.t -> Vec.t
(** [refine s p] is [p] put back onto the sphere from its centre (the robust mode: o + t·d is off
    by rounding errors of the size of the ray's length, a point projected from the centre by those
    of the centre and radius only). *)

val ellipsoid_refine : ellipsoid -> Vec.t -> Vec.t
(** [ellipsoid_refine e p] is [refine] in object space. *)

val stats_rows : Stats.t -> Stats.row list
(** [stats_rows s] is the statistics rows of spheres and ellipsoids, as POV-Ray names them. *)
