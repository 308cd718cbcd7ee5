(** Errors and warnings in scenes: values with a location, printed in one place ([bin/]). *)

type t = { loc : Loc.t; msg : string; notes : (Loc.t * string) list }
(** A main message at [loc], with located sub-messages ("included from …", "did you mean …"). *)

exception Scene_error of t
(** The one exception that carries a scene error; it is caught in exactly one place. *)

val raise_at : Loc.t -> ('a, unit, string, 'b) format4 -> 'a
(** [raise_at loc fmt …] raises [Scene_error] with a formatted message at [loc]. *)

val raise_notes : Loc.t -> (Loc.t * string) list -> string -> 'a
(** [raise_notes loc notes msg] raises [Scene_error] with sub-messages. *)

val render : source:(string -> string option) -> kind:string -> t -> string
(** [render ~source ~kind e] is the printed form: "file:line:col: kind: msg", the source line with a
    caret under the column, then the notes. [source file] gives a file's text when it can be read. *)
