(** Running povml and POV-Ray as separate processes, timed, each in a private directory. *)

type renderer = Povml of string | Povray of string  (** the renderer and its executable *)

val name : renderer -> string
(** [name r] is "povml" or "POV-Ray". *)

val find_povray : string option -> (string, string) result
(** [find_povray path] is POV-Ray's executable: [path] when given, else the environment variable
    [POVRAY], else [povray] found in [PATH]; an error message saying how to install it otherwise. *)

val temp_dir : string -> string
(** [temp_dir prefix] creates a new private directory under /tmp (where Debian's POV-Ray may write). *)

val remove_tree : string -> unit
(** [remove_tree dir] deletes [dir] and everything in it, ignoring errors. *)

type failure = {
  code : int;  (** exit status (128 + signal number when killed) *)
  message : string;  (** the renderer's first error line, or its last output line *)
  unsupported : bool;  (** povml's usage error (exit 2) or a "not supported" message *)
}

type outcome = { seconds : float;  (** wall time of the process *) image : (Encode.t, failure) result }

val render : ?shown:string -> renderer -> dir:string -> scene:string -> out:string -> string list -> outcome
(** [render ?shown r ~dir ~scene ~out switches] runs [r] on [scene] (an absolute path) with [+O out]
    and [switches] in the working directory [dir], output to [dir]/render.log; both renderers read
    the same empty ini file (env [POVINI]), not the system's. Ends with the PNG read back, or the failure, whose
    message names the scene [shown] (default [scene]). *)

val median : float list -> float
(** [median xs] is the median (the mean of the two middle values for an even count; nan for []). *)
