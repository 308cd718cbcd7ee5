(** Directives (docs/povray-rules.md §11.3), run as the token stream is read. *)

val directive_names : string list
(** [directive_names] are the directives povml knows, without the '#'. *)

val directive : Reader.st -> string -> Loc.t -> unit
(** [directive st name loc] runs the directive [#name] read at [loc]. *)

val invoke : Reader.st -> Value.macro -> Loc.t -> unit
(** [invoke st m loc] reads the arguments of a call of [m] at [loc] and starts reading its body. *)
