(** The settings [povml report] sweeps, and what it measured for each. *)

type setting = {
  antialias : float option;  (** the +A threshold, [None] for -A *)
  method_ : int;  (** +AM (used only with antialiasing) *)
  depth : int;  (** +R (used only with antialiasing) *)
  trace_level : int option;  (** a max_trace_level that overrides the scene's, or the scene's own *)
}

val settings :
  aa:bool -> trace:bool -> thresholds:float list -> methods:int list -> depths:int list -> trace_levels:int list -> setting list
(** [settings ~aa ~trace ~thresholds ~methods ~depths ~trace_levels] is the sweep: with [aa], -A then
    every method × depth × threshold (in that nesting order); with [trace], -A with each of
    [trace_levels]; always without duplicates. *)

val threshold : float -> string
(** [threshold t] is [t] as a switch value with at least one decimal ("0.3", "0.0", "0.05"). *)

val switches : setting -> string list
(** [switches s] is the antialiasing switches of [s]: ["-A"] or ["+A"t; "+AM"m; "+R"d]. *)

val label : setting -> string
(** [label s] names [s] in tables and plots: its switches, then "max_trace_level N" when it overrides. *)

val with_trace_level : string -> int -> string
(** [with_trace_level text n] is the scene text [text] followed by a [global_settings] block that
    sets max_trace_level to [n]; both renderers let a later block override the earlier value. *)

(** What one renderer did with one setting. *)
type measured =
  | Rendered of { times : float list;  (** wall seconds of each run *) median : float; cmp : Compare.t  (** against the ground truth *) }
  | Not_supported of string  (** the renderer refused the setting: its message *)
  | Failed of string  (** the render failed: the renderer's message *)

type row = { setting : setting; povml : measured; povray : measured }

type scene = {
  path : string;  (** the scene file as given *)
  stem : string;  (** a name for its files in the output directory, unique in the report *)
  width : int;
  height : int;
  switches : string list;  (** the switches every render of the scene got, besides the swept ones *)
  truth : string list;  (** the ground truth's switches (POV-Ray) *)
  truth_seconds : float;  (** wall time of the ground-truth render *)
  runs : int;  (** timed runs per setting and renderer *)
  rows : row list;
}

val get : row -> [ `Povml | `Povray ] -> measured
(** [get row r] is what renderer [r] did with [row]'s setting. *)

val front : scene -> [ `Povml | `Povray ] -> row list
(** [front scene r] is the rows on renderer [r]'s Pareto front of (median time, RMSE), by
    increasing time; settings the renderer did not render are left out. *)
