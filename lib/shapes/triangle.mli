(** Standalone triangles and smooth triangles as POV-Ray sets them up (docs/povray-rules.md §2.4, §2.5). *)

type t = private {
  nx : float; ny : float; nz : float;  (** unit normal *)
  dist : float;  (** −N·P1 *)
  x1 : float; y1 : float; z1 : float;
  x2 : float; y2 : float; z2 : float;
  x3 : float; y3 : float; z3 : float;
  axis : float;  (** dominant axis of the normal (0, 1, 2) *)
  px : float; py : float; pz : float;  (** smooth: Perp, so that u = (P − P1)·Perp *)
  vaxis : float;  (** smooth: dominant axis of P3 − P2 *)
  m1x : float; m1y : float; m1z : float;  (** smooth: vertex normals *)
  m2x : float; m2y : float; m2z : float;
  m3x : float; m3y : float; m3z : float;
}

val max3_coordinate : float -> float -> float -> int
(** [max3_coordinate x y z] is the index of the largest value; on ties the later axis wins. *)

val needs_swap : int -> Vec.t -> Vec.t -> Vec.t -> bool
(** [needs_swap axis p1 p2 p3] tells whether P1 and P2 are swapped for a consistent winding in the
    projection along [axis]. *)

val smooth_setup : round:(Vec.t -> Vec.t) -> Vec.t -> Vec.t -> Vec.t -> Vec.t * int
(** [smooth_setup ~round p1 p2 p3] is Perp (scaled) and the interpolation axis; [round] models the
    precision Perp is stored in. *)

val flat : Vec.t -> Vec.t -> Vec.t -> t option
(** [flat p1 p2 p3] is the set-up triangle, or [None] when it has no area. *)

val smooth : Vec.t -> Vec.t -> Vec.t -> Vec.t -> Vec.t -> Vec.t -> (t, unit) result option
(** [smooth p1 n1 p2 n2 p3 n3] (unit vertex normals) is [None] without area, [Some (Error ())] when
    the vertex normals are not all on one side of the face (POV-Ray hides it), else the triangle. *)

val intersect_within : Limits.t -> t -> Vec.t -> Vec.t -> float
(** [intersect_within lim t o d] is the depth along the unit direction [d] within [lim.near] …
    [lim.far], or infinity. *)

val intersect : t -> Vec.t -> Vec.t -> float
(** [intersect t o d] is [intersect_within Limits.pov t o d]: within 1e-6 … 1e7. *)

val smooth_normal : t -> Vec.t -> Vec.t
(** [smooth_normal t p] is the interpolated unit normal at [p]. *)

val bounds : t -> float array
(** [bounds t] is the box: min x, y, z, max x, y, z. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w t o d lo] is [intersect_within] with the scratch's limits when at least [lo], else
    infinity; the test and a hit are counted. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w t id o d lo n] pushes the one crossing, if any, as a hit of the member [id]. *)

val flat_normal : t -> Vec.t
(** [flat_normal t] is the face's unit normal. *)

val pov_box : t -> float array
(** [pov_box t] is POV-Ray's box: the corners' extent widened by EPSILON, in single precision. *)

val traits : Traits.t
(** [traits] is the traits of a flat triangle: tested at once, its box test free, a patch without
    an inside. *)

val smooth_traits : Traits.t
(** [smooth_traits] is the traits of a smooth triangle: a flat one's, but the whole scene's scale
    moves it as a matrix (its Scale renormalises the vertex normals). *)
