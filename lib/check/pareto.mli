(** Pareto fronts of settings that trade error for time. *)

val front : ('a -> float * float) -> 'a list -> 'a list
(** [front cost xs] is the elements of [xs] that no other element dominates, where [cost x] is
    [(time, error)], both minimised: sorted by increasing time (so by decreasing error); of equal
    costs only the first is kept. *)
