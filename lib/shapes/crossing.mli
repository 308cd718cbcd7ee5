(** What a shape that computes more than a depth at a crossing found there, and hands on with the
    crossing to the shading: a julia fractal's point and normal (its march's, which neither the
    depth nor the point alone gives back), a bicubic patch's normal and texture coordinates, a
    parametric surface's texture coordinates (POV-Ray keeps them in its Intersection: IPoint,
    INormal, Iuv). Stored flat, so that a search copies it without allocating. The other shapes
    report nothing. *)

type t
(** A crossing's report: its point, its unit normal and its texture coordinates (u, v). *)

val width : int
(** [width] is the number of floats a report takes in a float array ({!store}, {!load}). *)

val create : unit -> t
(** [create ()] is a report to be written ({!set}, {!blit}, {!load}): a room a worker reuses. *)

val none : t
(** [none] is the report of a hit whose shape reports nothing; never written. *)

val set : t -> Vec.t -> Vec.t -> float -> float -> unit
(** [set c p n u v] makes [c] the report of the crossing at the point [p], with the normal [n]
    and the texture coordinates (u, v). *)

val blit : t -> t -> unit
(** [blit src dst] makes [dst] the report [src] is. *)

val copy : t -> t
(** [copy c] is a fresh report equal to [c], which later writes to [c] leave as it is. *)

val store : t -> float array -> int -> unit
(** [store c a k] writes [c] into [a] at [k] ({!width} floats). *)

val load : float array -> int -> t -> unit
(** [load a k c] makes [c] the report stored in [a] at [k]. *)

val point : t -> Vec.t
(** [point c] is the crossing's point. *)

val point_x : t -> float
val point_y : t -> float

val point_z : t -> float
(** [point_x c], [point_y c], [point_z c] are the coordinates of [point c]. *)

val normal : t -> Vec.t
(** [normal c] is the normal the shape computed at the crossing (zero where it computes none
    there: a parametric surface's comes from (u, v) when needed). *)

val u : t -> float
val v : t -> float

val uv : t -> Vec.t
(** [u c] and [v c] are the crossing's texture coordinates, [uv c] is (u, v, 0). *)
