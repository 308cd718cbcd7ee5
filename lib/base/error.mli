(** Errors and warnings in scenes: values with a location, printed in one place ([bin/]). *)

(** What went wrong, which decides povml's exit status (1, 3 or 4). *)
type kind =
  | Scene  (** the scene is wrong: syntax, types, values *)
  | Limit  (** the scene went past one of povml's limits (loop iterations, nesting, objects …) *)
  | Access  (** the scene asked for a file it may not read or write *)

type t = { loc : Loc.t; msg : string; notes : (Loc.t * string) list; kind : kind }
(** A main message at [loc], with located sub-messages ("included from …", "did you mean …"). *)

exception Scene_error of t
(** The one exception that carries a scene error; it is caught in exactly one place. *)

val raise_at : Loc.t -> ('a, unit, string, 'b) format4 -> 'a
(** [raise_at loc fmt …] raises [Scene_error] with a formatted message at [loc]. *)

val limit_at : Loc.t -> ('a, unit, string, 'b) format4 -> 'a
(** [limit_at loc fmt …] raises [Scene_error] of kind [Limit]. *)

val access_at : Loc.t -> ('a, unit, string, 'b) format4 -> 'a
(** [access_at loc fmt …] raises [Scene_error] of kind [Access]. *)

val limit_error : Loc.t -> string -> t
(** [limit_error loc msg] is an error of kind [Limit] without notes. *)

val warning : Loc.t -> string -> t
(** [warning loc msg] is a warning (kind [Scene]) without notes. *)

val raise_notes : Loc.t -> (Loc.t * string) list -> string -> 'a
(** [raise_notes loc notes msg] raises [Scene_error] with sub-messages. *)

val render : source:(string -> string option) -> kind:string -> t -> string
(** [render ~source ~kind e] is the printed form: "file:line:col: kind: msg", the source line with a
    caret under the column, then the notes. [source file] gives a file's text when it can be read. *)
