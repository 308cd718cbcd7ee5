(** Objects: the primitives, meshes, unions and light sources, and their modifiers (POVRAY-3.7 §2,
    §14, §16.4). *)

val unsupported_rvalue_set : unit Reader.Names.t
(** [unsupported_rvalue_set] are the keywords of values povml cannot make yet. *)

(** A light source as read: alone, or with its looks_like object (§19.2), kept as a union of the
    light and the object so that later transforms move both. *)
type light_source = Lone of Scene.light | Shaped of Value.obj

val parse_light_source : Reader.st -> light_source
(** [parse_light_source st] reads a light_source (the keyword is the next token). *)

val parse_object : Reader.st -> Value.obj
(** [parse_object st] reads an object with its modifiers. *)

val object_follows : Reader.st -> bool
(** [object_follows st] tells whether an object (keyword or identifier) comes next. *)

val add_object : Reader.st -> Value.obj -> unit
(** [add_object st o] adds [o] to the scene, dissolving unions (§16.4, §16.5). *)
