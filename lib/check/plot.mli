(** The report's plot: error against time for both renderers, as self-contained SVG text. *)

val log_ticks : float -> float -> float list
(** [log_ticks lo hi] is the tick values of a logarithmic axis from [lo] to [hi] (0 < lo < hi):
    1, 2, 5 × 10^k inside the range; 1, 1.5, 2, 3 … 9 × 10^k when that gives fewer than three; three
    evenly spaced values when even that gives fewer than two. *)

val escape : string -> string
(** [escape s] is [s] with the characters XML reserves written as entities. *)

val svg : Sweep.scene list -> string
(** [svg scenes] is an SVG document with one panel per scene: RMSE against the ground truth
    against median wall time, both on log scales; povml's settings as circles, POV-Ray's as squares,
    each renderer's Pareto front as a line through filled, labelled points; settings a renderer did
    not render are counted below the panel, not drawn; zero error is drawn on a row of its own
    below the axis. *)
