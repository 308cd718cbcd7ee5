(** POV-Ray's deterministic 2-D jitter for antialiasing samples (docs/povray-rules.md §9.2). *)

val jx : float -> float -> float
(** [jx x y] is the horizontal jitter offset in [-0.5, 0.5] for the sample position (x, y). *)

val jy : float -> float -> float
(** [jy x y] is the vertical jitter offset in [-0.5, 0.5] for the sample position (x, y). *)
