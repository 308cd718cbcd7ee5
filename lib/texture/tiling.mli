(** The tiling pattern (pattern.cpp tiling_pattern): tilings 1…27 of the XZ plane. *)

val value : int -> Vec.t -> float
(** [value n p] is tiling [n]'s value at [p] (y ignored): with one kind of tile, 1 on a tile's edge
    falling to 0 inside; with several kinds, a band of values per kind; 25–27 are Penrose's. Any
    other [n] gives 1, as POV-Ray's switch does. *)
