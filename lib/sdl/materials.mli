(** Pigments, finishes, textures and interiors (docs/povray-rules.md §5, §10.1). *)

val ident_of_kind : Reader.st -> (Value.t -> 'a option) -> 'a option
(** [ident_of_kind st f] consumes an identifier whose value [f] accepts, and returns [f]'s result. *)

val map_entries : Reader.st -> string -> loc:Loc.t -> value:(unit -> float) -> (float -> 'a) -> 'a array
(** [map_entries st what ~loc ~value entry] reads the entries of a map block after its '{' up to
    its '}': ["\[" VALUE \[,\] ENTRY "\]"], in the order written, at most 256 and at least one (an
    empty map is an error at [loc]); [value] reads the value, [entry] what follows it (its ']'
    included) given the value rounded to single precision. *)

val block_pattern : Reader.st -> Scene.pattern option -> (Scene.pattern * int) option
(** [block_pattern st current] is the block pattern (checker, hexagon, brick, square, triangular,
    cubic) named by the next token, not consumed, with the number of its entries; a brick keeps
    [current]'s size and mortar. None for any other token. *)

val is_pattern_start : Reader.st -> bool
(** [is_pattern_start st] tells whether the next token names a pattern (those povml lacks too). *)

val parse_colour_map : Reader.st -> string -> Scene.map_entry array
(** [parse_colour_map st kw] reads the block of a [color_map] (written [kw]) after the keyword. *)

val parse_pigment_map : ?average:bool -> Reader.st -> Scene.pigment_entry array
(** [parse_pigment_map ~average st] (an [average]'s entries may leave their weight out, 1) reads the block of a [pigment_map] after the keyword: entries, or a
    declared map's identifier. *)

val uv_mapped : Scene.pigment -> Scene.pigment
(** [uv_mapped p] is [p] evaluated at the hit's (u, v, 0) ([uv_mapping]). *)

val parse_pigment : Reader.st -> Scene.pigment -> Scene.pigment
(** [parse_pigment st base] reads a pigment block that modifies [base]. *)

val parse_normal : Reader.st -> Scene.normal option -> Scene.normal
(** [parse_normal st base] reads a normal block that modifies [base] (else the default texture's
    normal, else a new one: bump size 0.5, accuracy 0.02). *)

val parse_default_normal : Reader.st -> Scene.normal option -> Scene.normal
(** [parse_default_normal st base] is {!parse_normal} for [#default], where a normal may have no
    pattern ([No_pattern]): it is only the base that later normals edit. *)

val parse_finish : Reader.st -> Scene.finish -> Scene.finish
(** [parse_finish st base] reads a finish block that modifies [base]. *)

val parse_interior : Reader.st -> Scene.interior -> Scene.interior
(** [parse_interior st base] reads an interior block that modifies [base]. *)
