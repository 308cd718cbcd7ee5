(** The sphere (docs/povray-rules.md §2.2), and the ellipsoid: a sphere mapped by a transform (§14.5 (b)). *)

type t = { cx : float; cy : float; cz : float; radius : float; r2 : float }
(** Centre, radius as written (the normal is scaled by its reciprocal), radius². *)

type uv_frame = { uv_trans : Transform.t; uv_centre : Vec.t }
(** Where a moved sphere takes its UV coordinates (Sphere::UVCoord): the world point brought back
    by the inverse of [uv_trans], every modifier the sphere got (POV-Ray's UV_Trans), and the
    centre as POV-Ray brings it back the same way, computed once. *)

type ellipsoid = { sp : t; etr : Transform.t; euv : uv_frame option }
(** The object-space sphere [sp] mapped by [etr], and its UV frame. *)

type placed = { ps : t; puv : uv_frame }
(** A sphere whose modifiers were baked into its centre and radius ([ps], traced as a plain
    sphere), with the frame its UV coordinates are taken in. *)

val make : Vec.t -> float -> t
(** [make centre radius] is the sphere. *)

val ellipsoid : t -> Transform.t -> Transform.t option -> ellipsoid
(** [ellipsoid sp etr uv_trans] is [sp] mapped by [etr], its UV coordinates taken in the frame of
    [uv_trans] (its centre mapped by [etr], then back by [uv_trans]'s inverse), or in object
    space without one. *)

val placed : t -> Transform.t -> placed
(** [placed s uv_trans] is [s] with the UV frame of [uv_trans]. *)

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
(** [ellipsoid_hits] is [hits] for an ellipsoid; the hit points are the object-space points
    mapped back. *)

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

val uv_of : Vec.t -> Vec.t -> Vec.t
(** [uv_of q c] is Sphere::UVCoord of the point [q] of a sphere of centre [c], both in the UV
    frame: (u, v, 0) with u = θ/2π, θ the angle about the y axis from +x towards +z (0 at a pole,
    π when z = 0 and x ≤ 0), and v = 0.5 + asin(y)/π, from the direction divided by its length;
    (0, 0, 0) at the centre (where POV-Ray leaves its result unset). *)

val uv : t -> Vec.t -> Vec.t
(** [uv s p] is the UV coordinates of an unmoved sphere at the world point [p]. *)

val placed_uv : placed -> Vec.t -> Vec.t
(** [placed_uv s p] is those of a moved sphere, in its UV frame. *)

val ellipsoid_uv : ellipsoid -> Vec.t -> Vec.t
(** [ellipsoid_uv e p] is those of an ellipsoid, in its UV frame (else [p] and the object-space
    centre as they are, as POV-Ray without a UV_Trans). *)

val traits : Traits.t
(** [traits] is its kind's traits: a sphere is cheaper to test than its box, and its box test is
    free. *)

val ellipsoid_traits : Traits.t
(** [ellipsoid_traits] is the traits of an ellipsoid: a sphere's, but costlier to test than its
    box. *)
