(** Textures as POV-Ray 3.7 reads them (Parse_Texture, Parse_Tiles, Parse_Material,
    Link_Textures): plain textures, layers, patterned textures (a [texture_map], block patterns
    with listed textures, [tiles], [average]) and materials. *)

val link : Reader.st -> Loc.t -> Scene.texture option -> Scene.texture -> Scene.texture
(** [link st loc old t] is [t] laid over [old] (Link_Textures: the texture written last is on
    top). A patterned texture cannot be layered, over or under: a located error at [loc]. In
    scenes of version 3.1 and older, a layer with one below it has its filter turned into
    transmit, as POV-Ray does. *)

val parse : Reader.st -> Scene.texture
(** [parse st] reads a texture block after the [texture] keyword: a texture identifier or the
    default texture, modified by pigment, normal and finish (blocks, or their identifiers, which
    stand for blocks here) and transforms; or, when nothing modified it, [tiles] or a pattern with
    its modifiers and texture_map (or listed textures for a block pattern). *)

val parse_body : Reader.st -> close:Token.kind -> Scene.texture
(** [parse_body st ~close] reads what {!parse} reads, up to and including [close] (['}'], or
    [']'] for a texture_map entry). *)

val layers : Reader.st -> Scene.texture option
(** [layers st] reads [texture {…}] blocks as long as they follow each other, each laid over the
    ones before ({!link}); None when none follows. *)

val parse_texture_map : Reader.st -> bool -> Scene.texture_entry array
(** [parse_texture_map st average] reads the block of a [texture_map] after the keyword: entries
    [\[v TEXTURE\]] (values single precision; for an [average] they may be left out and are 1),
    or a declared map's identifier. *)

val parse_material : Reader.st -> Value.material -> Value.material
(** [parse_material st m] reads a material block after the keyword, modifying [m]: a material
    identifier's textures are laid over [m]'s and its interior replaces [m]'s; then [texture] and
    [interior_texture] blocks are laid over, [interior] edits the interior, and transforms move the
    texture (not the interior texture, as in POV-Ray). *)

val no_material : Value.material
(** [no_material] is a material with no texture, interior texture or interior. *)
