(** povml's exit statuses, documented in [--help] and README.md, and the last word on a run that
    ends by a signal or an unexpected exception. *)

val scene_error : Error.kind -> int
(** [scene_error k] is the status for a scene error of kind [k]: 1 (the scene is wrong), 3 (a limit
    was reached), 4 (file access refused). *)

val cannot_write : int
(** [cannot_write] is 5: the image could not be written. *)

val internal_error : int
(** [internal_error] is 70 (EX_SOFTWARE): a bug in povml. *)

val man : Cmdliner.Manpage.block list
(** [man] is the EXIT STATUS section of [povml --help]. *)

val guard : (unit -> int) -> int
(** [guard run] is [run ()]; but after SIGINT or SIGTERM ([Interrupt.install]) it prints
    "povml: interrupted by SIGINT; no image was written" and is 130 (143 for SIGTERM), unless
    [run ()] is 0 (the image was written first), and an unexpected exception is printed as an
    internal error without a backtrace, status 70. *)
