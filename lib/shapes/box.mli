(** The box (docs/povray-rules.md §15.1): its corners sorted per axis, in world space or mapped by a
    transform (§14.5 (a)). The side a hit is on is 1–6 for X−, X+, Y−, Y+, Z−, Z+. *)

type t = { x0 : float; y0 : float; z0 : float; x1 : float; y1 : float; z1 : float }
(** The lower and upper corners. *)

type moved = { bx : t; btr : Transform.t }
(** [bx] mapped by [btr]. *)

val make : Vec.t -> Vec.t -> t
(** [make lo hi] is the box with corners [lo] ≤ [hi]. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w b o d lo] is the nearest crossing at least [lo] (Box::Intersect), its side left in
    [w.part]; or infinity. Of two equal depths (a ray through an edge) the far crossing's side wins. *)

val moved_depth : Scratch.t -> moved -> Vec.t -> Vec.t -> float -> float
(** [moved_depth] is [depth] with the ray brought into object space, not renormalised. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w b id o d lo n] pushes the near crossing (beyond the near limit) and the far one, each
    at least [lo], as hits of the member [id] (Box::All_Intersections); it is the new count. *)

val moved_hits : Scratch.t -> moved -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [moved_hits] is [hits] through the transform. *)

val crossed : Scratch.t -> t -> float -> float -> float -> float -> float -> float -> bool
(** [crossed w b px py pz vx vy vz] is Box::Intersect of the ray from (px, py, pz) along (vx, vy,
    vz) (in the box's space, not renormalised): whether it meets the box with its far crossing
    beyond the near limit, the crossings left in [w.slab] (the near one 0 when the ray starts
    inside), the sides in [w.side_near] and [w.side_far]. It counts nothing (the containers of
    other shapes use it). *)

val side_normal : int -> Vec.t
(** [side_normal side] is the outward axis of the side (1–6). *)

val moved_normal : moved -> int -> Vec.t
(** [moved_normal m side] is the side's axis by the inverse transpose, normalised (§14.6). *)

val inside : t -> Vec.t -> bool
(** [inside b p] is Box::Inside: the closed box, its surface included. *)

val moved_inside : moved -> Vec.t -> bool
(** [moved_inside] is [inside] in object space. *)

val bounds : t -> float array
(** [bounds b] is the box itself (min x, y, z, max x, y, z). *)

val moved_bounds : moved -> float array
(** [moved_bounds m] is the box of the mapped corners. *)

val pov_box : t -> float array
(** [pov_box b] is POV-Ray's box of the box. *)

val moved_pov_box : moved -> float array
(** [moved_pov_box m] is that box mapped by the transform. *)

val uv : t -> int -> Vec.t -> Vec.t
(** [uv b side p] is Box::UVCoord of the point [p] on [side] (1–6): the point relative to the box,
    each coordinate from 0 to 1, placed on a cube map's cross, (u, v, 0): X− at u = z/4, v =
    1/3 + y/3; X+ at u = 3/4 − z/4; Y− at u = 1/4 + x/4, v = z/3; Y+ at v = 1 − z/3; Z− at u =
    1 − x/4; Z+ at u = 1/4 + x/4, v = 1/3 + y/3. *)

val moved_uv : moved -> int -> Vec.t -> Vec.t
(** [moved_uv m side p] is [uv] of the object-space point. *)

val traits : Traits.t
(** [traits] is the traits of a box in world space: as cheap as its own box, which is free to
    test. *)

val moved_traits : Traits.t
(** [moved_traits] is the traits of a box mapped by a transform: costlier to test than its box. *)
