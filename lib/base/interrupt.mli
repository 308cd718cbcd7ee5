(** SIGINT and SIGTERM during a render: they stop the work at the next allocation, and the code
    that must not stop half-way (creating or removing a file, reaping workers) holds them back. *)

exception Interrupted
(** Raised, once [install] has run, by SIGINT or SIGTERM at the program's next allocation or
    blocking system call. *)

val install : unit -> unit
(** [install ()] makes SIGINT and SIGTERM raise [Interrupted], except a signal that was ignored
    when povml started (a background job of a script, [nohup]): it stays ignored. *)

val received : unit -> int option
(** [received ()] is the first of the installed signals that has arrived ([Sys.sigint] or
    [Sys.sigterm]), counting one held back by [hold] right now. *)

val check : unit -> unit
(** [check ()] raises [Interrupted] if [received ()] is a signal. *)

val hold : (unit -> 'a) -> 'a
(** [hold f] is [f ()] run with SIGINT and SIGTERM held back: a signal that arrives meanwhile
    raises nothing, neither in [f] nor after it, and is only recorded for [received]. *)

val commit : (unit -> ('a, 'e) result) -> ('a, 'e) result
(** [commit f] is [hold f], and when it is [Ok _] the work is done and [disarm] follows at once,
    so that a finished run is not reported as interrupted. *)

val disarm : unit -> unit
(** [disarm ()] makes later signals raise nothing: they are only recorded for [received]. *)

val exit_status : int -> int
(** [exit_status s] is the status of a process ended by signal [s], as the shell shows it: 130
    for [Sys.sigint], 143 for [Sys.sigterm]. *)

val name : int -> string
(** [name s] is ["SIGINT"] or ["SIGTERM"]. *)
