(** The pavement pattern (pattern.cpp pavement_pattern): tilings of the XZ plane by polyominoes,
    polyiamonds and polyhexes. *)

val value : int -> int -> int -> int -> int -> int -> Vec.t -> float
(** [value side tile number form interior exterior p] is the pavement's value at [p] (y ignored):
    0 inside a tile rising to 1 at its border; [side] 3, 4 or 6 (anything else is read as 3),
    [tile] and [number] choose the pavement, [form], [interior] and [exterior] shape its edges and
    corners, as the parser has reduced them. *)
