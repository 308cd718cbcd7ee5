(** The text object: a string set in a TrueType font, one extruded glyph per character
    (docs/povray-rules.md §15.9). *)

val parse : Reader.st -> Loc.t -> Value.obj
(** [parse st loc] reads the block of a text object written at [loc] (after the keyword) up to its
    modifiers: the font file is found like an include file and read through the access policy, the
    string decoded as the charset says, and the letters made a union (split like any union) turned
    by POV-Ray's <0.001, 0.001, 0.001> degrees. *)
