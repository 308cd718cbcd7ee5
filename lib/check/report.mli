(** [povml report]: each scene rendered by both renderers with every setting of a sweep, timed, and
    measured against one ground truth per scene; the results written as CSV, Markdown and SVG. *)

type config = {
  povml : string;  (** povml's executable *)
  povray : string;  (** POV-Ray's executable *)
  out_dir : string;  (** where report.csv, report.md, report.svg and one SVG per scene go *)
  switches : string list;  (** the user's switches, given to every render *)
  runs : int;  (** timed runs per setting and renderer *)
  truth : string list;  (** the ground truth's switches, rendered by POV-Ray *)
  settings : Sweep.setting list;
  progress : string -> unit;  (** receives one line per step *)
}

val default_truth : string list
(** [default_truth] is POV-Ray's most exact antialiasing: [+AM2 +R5 +A0.0]. *)

val prepare_out_dir : string -> (unit, string) result
(** [prepare_out_dir dir] creates [dir] (and its parents) when missing and checks that a file can be
    written in it. *)

val stems : string list -> string list
(** [stems paths] is a distinct file name stem per scene path: its base name without [.pov], with
    [-2], [-3] … appended to repeats. *)

val measure_scene : config -> dir:string -> stem:string -> string -> (Sweep.scene, string) result
(** [measure_scene config ~dir ~stem path] renders the ground truth and the sweep of scene [path]
    in the private directory [dir]; an error when the ground truth cannot be rendered. *)

val write : config -> Sweep.scene list -> (string list, string) result
(** [write config scenes] writes report.csv, report.md, report.svg (every scene) and [stem].svg per
    scene into [config.out_dir]; the paths written, or the first error. *)

val run : config -> string list -> (Sweep.scene list * (string * string) list, string) result
(** [run config paths] measures each scene in turn and rewrites the outputs after each one; the
    scenes measured and the [(path, message)] of those whose ground truth failed, or an error when
    the outputs cannot be written. *)
