(** POV-Ray's bounding cylinders of the segments of a lathe or a surface of revolution
    (bounding/bcyl.cpp): each segment within a thick cylinder (two radii, two heights about the
    Y axis). The distinct radii and heights are intersected once per ray; the segments whose
    thick cylinder the ray meets are listed by their entry distance. *)

type entry = { r1 : int; r2 : int; h1 : int; h2 : int }
(** A segment's thick cylinder: the indices of its inner and outer radius and of its lower and
    upper height. *)

type t = {
  radius : float array;  (** the distinct radii, squared *)
  height : float array;  (** the distinct heights *)
  entry : entry array;  (** one per segment *)
}

val make : float array -> float array -> float array -> float array -> t
(** [make r1 r2 h1 h2] is Create_BCyl of the segments' inner and outer radii and lower and upper
    heights: each distinct value kept once, in the order met. *)

val intersect : Scratch.t -> t -> float -> float -> float -> float -> float -> float -> int
(** [intersect w b px py pz dx dy dz] is Intersect_BCyl of the ray P + k·D (shape space, D of unit
    length): the number of segments whose thick cylinder it meets, listed in [w]'s bcyl room by
    entry distance (0 for a ray starting inside; a new entry before equal ones); an odd count of
    crossings lists the segment at its first. *)

val interval_depth : Scratch.t -> int -> float
(** [interval_depth w j] is the entry distance of the [j]-th listed segment. *)

val interval_segment : Scratch.t -> int -> int
(** [interval_segment w j] is the index of the [j]-th listed segment. *)
