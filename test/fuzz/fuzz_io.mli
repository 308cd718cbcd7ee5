(** What the deterministic fuzz runs share. *)

val write : string -> string -> unit
(** [write path text] writes [text] to the file [path], replacing it. *)

val keep : Unix.file_descr -> string -> unit
(** [keep fd text] makes the file open as [fd] hold [text], rewritten in place (opening with
    truncation costs a millisecond on ext4). *)

val set_timer : Unix.interval_timer -> float -> unit
(** [set_timer which seconds] arms the timer [which] once, [seconds] from now (0 disarms it). *)

val within : float -> (unit -> 'a) -> 'a option
(** [within budget f] is [Some (f ())], or [None] when [f] used more than [budget] seconds of CPU
    time (a CPU-time timer whose handler raises); a wall-clock timer of ten times [budget], whose
    signal ends the process, catches a run stuck outside OCaml code. *)
