(** The object parser: every object, primitive or CSG, as read, with its modifiers (docs/povray-rules.md §2,
    §14, §15, §16). *)

val unsupported_rvalue_set : unit Reader.Names.t
(** [unsupported_rvalue_set] are the keywords of values povml cannot make yet. *)

val parse_light_source : Reader.st -> Lights.light_source
(** [parse_light_source st] reads a light_source (the keyword is the next token). *)

val parse_object : Reader.st -> Value.obj
(** [parse_object st] reads an object with its modifiers. *)

val object_follows : Reader.st -> bool
(** [object_follows st] tells whether an object (keyword or identifier) comes next. *)

