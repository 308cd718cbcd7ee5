(** Objects: the primitives, meshes, unions and light sources, and their modifiers (POVRAY-3.7 §2,
    §14, §16.4). *)

val unsupported_rvalue_set : unit Reader.Names.t
(** [unsupported_rvalue_set] are the keywords of values povml cannot make yet. *)

val parse_light : Reader.st -> Scene.light
(** [parse_light st] reads a light_source (the keyword is the next token). *)

val parse_object : Reader.st -> Value.obj
(** [parse_object st] reads an object with its modifiers. *)

val object_follows : Reader.st -> bool
(** [object_follows st] tells whether an object (keyword or identifier) comes next. *)

val add_object : Reader.st -> Value.obj -> unit
(** [add_object st o] adds [o] to the scene, dissolving unions (§16.4, §16.5). *)
