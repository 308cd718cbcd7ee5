(** The report's tables: CSV (one line per scene, setting and renderer) and Markdown. *)

val csv_field : string -> string
(** [csv_field s] is [s] quoted for CSV when it holds a comma, a quote or a line break. *)

val csv : Sweep.scene list -> string
(** [csv scenes] is the CSV text: a header, then per scene a line for the ground truth and a line per
    setting and renderer with the status, times, error metrics and whether it is on the renderer's
    Pareto front. *)

val markdown : plot:(Sweep.scene -> string option) -> Sweep.scene list -> string
(** [markdown ~plot scenes] is the Markdown report: how it was measured, then per scene the plot
    ([plot scene] is its image's path, if any) and a table of every setting for both renderers. *)
