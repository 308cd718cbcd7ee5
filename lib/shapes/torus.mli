(** The torus (docs/povray-rules.md §15.5): centred at the origin of its own space, symmetric about the Y
    axis, the tube's core circle of radius [major] in the XZ plane, mapped to the world by its
    transform (a torus always has one, §14.4). Rays are brought into torus space with the
    direction renormalised (§14.5 (b)); depths are returned in world units. *)

type t = {
  major : float;  (** R, the core circle's radius *)
  minor : float;  (** r, the tube's radius (R < r is a spindle torus) *)
  sturm : bool;  (** always solve with Sturm sequences *)
  tr : Transform.t;  (** torus space to world *)
}

val depth_tolerance : float
(** 1e-4: POV-Ray keeps a torus hit only beyond this world depth (§15.5, §20 item 10). *)

val solve : Scratch.t -> t -> Vec.t -> Vec.t -> int
(** [solve w t o d] intersects the ray from [o] along the unit [d] (world space) with the torus,
    as POV-Ray's [Torus::Intersect]: −1 when the thick-cylinder pre-test rejects the ray (the
    solver is not called), else the number n of roots found, whose world depths
    [(root + closer)/len] are in [depths w] [.(0 … n−1)], unfiltered, in POV-Ray's order (the
    solver's roots from the last). *)

val depths : Scratch.t -> float array
(** [depths w] is the array [solve] writes its depths into ([w.depths], room for 4). *)

val eliminated : Scratch.t -> bool
(** [eliminated w] is true when the last [solve] dropped a root at 0 (a ray leaving the surface). *)

val intersections : Scratch.t -> t -> near:float -> Vec.t -> Vec.t -> float array -> int
(** [intersections w t ~near o d out] writes every hit with [near] < depth < 1e7 into [out] (room
    for 4), in POV-Ray's order ([All_Intersections] with [near] = 1e-4), and returns their number. *)

val nearest : Scratch.t -> t -> near:float -> Vec.t -> Vec.t -> float -> float
(** [nearest w t ~near o d lo] is the smallest depth with [near] < depth < 1e7 and depth ≥ [lo], or
    infinity. *)

val thick_cylinder : Vec.t -> Vec.t -> float -> float -> float -> float -> bool
(** [thick_cylinder p v h1 h2 r1 r2] is POV-Ray's [Test_Thick_Cylinder] in torus space: whether the
    ray from [p] along the unit [v] meets (at a parameter in (1e-10, 1e7)) the caps [y = h1], [y = h2]
    within [r1 ≤ x²+z² ≤ r2] or the cylinders [x²+z² = r1] or [r2] within [h1 ≤ y ≤ h2]. It only
    rejects rays that cannot hit the torus. *)

val normal : t -> Vec.t -> Vec.t
(** [normal t p] is the unit outward normal at the world point [p] of the surface: in torus space
    [P − R·(P.x, 0, P.z)/√(P.x²+P.z²)] (the core-circle point taken as 0 on the axis), by the
    inverse transpose, normalised (§14.6). *)

val inside : t -> Vec.t -> bool
(** [inside t p] is POV-Ray's [Torus::Inside] of the world point [p]: within the tube, surface
    included. *)

val box : t -> float array
(** [box t] is the torus-space box [[| −(R+r); −r; −(R+r); R+r; r; R+r |]] (lower corner, upper
    corner), before the transform. *)

val crossings : Scratch.t -> t -> Vec.t -> Vec.t -> float array -> int
(** [crossings w t o d out] writes every depth at which the ray crosses the torus within its limits
    (beyond 1e-4 in world units, none in the robust mode; below 1e7) into [out] (room for 4), in
    POV-Ray's order, and returns their number; the torus statistics are counted ("Torus", "Torus
    Bound", "Roots tested", "eliminated"). *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w t o d lo] is the nearest of those depths at least [lo], or infinity; counted the same. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w t id o d lo n] pushes the crossings at least [lo] as hits of the member [id]
    (Torus::All_Intersections); it is the new count. *)

val bounds : t -> float array
(** [bounds t] is the box of [box t]'s mapped corners. *)

val pov_box : t -> float array
(** [pov_box t] is Torus::Compute_BBox: Make_BBox of [box t], then Recompute_BBox through the
    transform every torus has (§15.5, §15.8). *)

val traits : Traits.t
(** [traits] is its kind's traits: [Traits.default], and [sturm] alone turns Sturm sequences on. *)

val uv : t -> Vec.t -> Vec.t
(** [uv t p] is Torus::UVCoord at the world point [p], in torus space: u = 1 − (atan2(z, x) + π)/2π,
    v = (atan2(y, √(x² + z²) − R) + π)/2π, as (u, v, 0). *)
