(** The vertices (or normals) of a mesh { }, merged when equal as POV-Ray merges them: each
    distinct triple is stored once and named by its index. *)

type t
(** A table of distinct triples, in the order they were first inserted. *)

val create : unit -> t
(** [create ()] is an empty table. *)

val insert : t -> float -> float -> float -> int
(** [insert t x y z] is the index of the triple [(x, y, z)] in [t], added at the end when no equal
    triple is there yet. *)

val to_array : t -> float array
(** [to_array t] is the distinct triples of [t], flattened: x, y, z of index 0, then of index 1, … *)
