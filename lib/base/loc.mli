(** Source locations: where a token, value or error comes from. *)

type t = { file : string; line : int; col : int }
(** [line] and [col] count from 1; [col] is in bytes. *)

val none : t
(** [none] is the location of things that have no source (built-in defaults). *)

val to_string : t -> string
(** [to_string l] is "file:line:column". *)
