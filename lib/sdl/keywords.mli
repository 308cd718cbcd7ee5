(** POV-Ray 3.7's reserved words (parser/reswords.cpp), each with what povml does with it: one
    table, from which the interpreter takes the words it reads, the words that start an object,
    and the words it reports as "not supported yet". A new shape's keyword is one entry here
    (status [Object]) and one case in [Objects]. *)

type status =
  | Read  (** a word povml reads (but not the first word of an object) *)
  | Object  (** the first word of an object povml reads: a shape, a CSG, [object] *)
  | Not_supported  (** a word povml will read later: meeting it is a located "not supported yet" *)
  | Object_not_supported  (** an object povml does not render yet, "not supported yet" in a union too *)
  | Reserved
      (** one of POV-Ray's other reserved words, which povml does not read: it cannot be declared,
          and found out of place it is the user's error *)

val table : (string * status) list
(** [table] is every reserved word povml knows, once, with its status. *)

val words : (status -> bool) -> string list
(** [words keep] is the words of [table] whose status satisfies [keep], in the table's order. *)
