(** Pigments, finishes, textures and interiors (POVRAY-3.7 §5, §10.1). *)

val ident_of_kind : Reader.st -> (Value.t -> 'a option) -> 'a option
(** [ident_of_kind st f] consumes an identifier whose value [f] accepts, and returns [f]'s result. *)

val parse_colour_map : Reader.st -> string -> Scene.map_entry array
(** [parse_colour_map st kw] reads the block of a [color_map] (written [kw]) after the keyword. *)

val parse_pigment_map : Reader.st -> Scene.pigment_entry array
(** [parse_pigment_map st] reads the block of a [pigment_map] after the keyword: entries, or a
    declared map's identifier. *)

val parse_pigment : Reader.st -> Scene.pigment -> Scene.pigment
(** [parse_pigment st base] reads a pigment block that modifies [base]. *)

val parse_normal : Reader.st -> Scene.normal option -> Scene.normal
(** [parse_normal st base] reads a normal block that modifies [base] (else the default texture's
    normal, else a new one: bump size 0.5, accuracy 0.02). *)

val parse_finish : Reader.st -> Scene.finish -> Scene.finish
(** [parse_finish st base] reads a finish block that modifies [base]. *)

val parse_texture : Reader.st -> Scene.texture -> Scene.texture
(** [parse_texture st base] reads a texture block that modifies [base]; [texture { uv_mapping … }] is the texture read after the keyword with its pigment uv-mapped (not supported yet when it has a normal). *)

val parse_interior : Reader.st -> Scene.interior -> Scene.interior
(** [parse_interior st base] reads an interior block that modifies [base]. *)
