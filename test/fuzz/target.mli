(** The fuzz target: one input through the interpreter and a tiny render, and whether what
    happened is allowed. Shared by the AFL++ executable and the deterministic run in the tests. *)

val limits : Scene_limits.t
(** [limits] are small limits, so that a legitimate but huge scene ends quickly with a limit error
    instead of looking like a hang: 10,000 loop iterations, macro calls and objects, macro depth
    1,000, nesting 2,000, 128 MiB; the default include depth. *)

type outcome =
  | Scene of int  (** the scene was read and rendered, with this many warnings *)
  | Refused of Error.t  (** the scene was refused with a located error ([Scene_error]) *)
  | Bug of string
      (** anything else: an exception that is not [Scene_error], or the error the interpreter makes
          of Stack_overflow and Out_of_memory when no limit stopped the scene first; described *)

val run : ?render:bool -> file:string -> string -> outcome
(** [run ?render ~file text] interprets [text] (named [file] in locations) with [limits] and, when
    [render] (the default) is set, compiles the scene and renders it at 8×8. Every exception but
    [Scene_error] becomes [Bug], with its backtrace when backtraces are recorded. *)
