(** The disc (docs/povray-rules.md §15.4) in the plane z = 0 of its canonical space, placed by a transform. *)

type t = {
  dtr : Transform.t;  (** canonical space to world *)
  dnx : float;
  dny : float;
  dnz : float;  (** the world normal, the same at every point *)
  or2 : float;  (** outer radius² *)
  ir2 : float;  (** hole radius² *)
}

val make : normal:Vec.t -> radius:float -> hole:float -> Transform.t -> t
(** [make ~normal ~radius ~hole tr] is the disc placed by [tr], with the world unit [normal]. *)

val crossings : Scratch.t -> t -> Vec.t -> Vec.t -> float array -> int
(** [crossings w dc o d out] is Disc::Intersect: 0 or 1 crossing, written as ([out.(0)] = world
    depth, [out.(1)] = 0.). The plane's crossing must be ahead in canonical units (s ≥ 0), within the
    ring (hole² ≤ r² ≤ radius²), and its world depth within the limits (1e-6 < depth < 1e7). *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w dc o d lo] is the crossing if at least [lo], else infinity. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w dc id o d lo n] pushes the crossing as a hit of the member [id]; it is the new count. *)

val normal : t -> Vec.t
(** [normal dc] is the world normal. *)

val inside : t -> Vec.t -> bool
(** [inside dc p] is Disc::Inside: the open half-space behind the plane, z < 0 in canonical space. *)

val small_tolerance : float
(** [small_tolerance] is SMALL_TOLERANCE, 1e-3: a disc's box is this thick on each side of its
    plane. *)

val bounds : t -> float array
(** [bounds dc] is the box of the canonical [−r, r]² × [−1e-3, 1e-3] box's mapped corners. *)

val pov_box : t -> float array
(** [pov_box dc] is Disc::Compute_BBox: Make_BBox(−r, −r, −1e-3, 2r, 2r, 2e-3) through the transform. *)

val traits : Traits.t
(** [traits] is its kind's traits: [Traits.default]. *)
