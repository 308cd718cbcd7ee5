(** A TrueType font file as a [text] object reads it (docs/povray-rules.md §15.9): the tables head, maxp,
    loca, hhea, hmtx, kern and cmap, glyph outlines from glyf (simple and composite), and the
    layout of a string along +x, as POV-Ray's truetype.cpp does it, its quirks included. *)

type t
(** A font read from a file. *)

val parse : string -> (t, string) result
(** [parse bytes] is the font in the file contents [bytes], or what is wrong with it. *)

val units_per_em : t -> int
(** [units_per_em f] is the head table's unitsPerEm. *)

val glyph_index : ?utf8:bool -> t -> int -> int
(** [glyph_index ?utf8 f c] is the glyph of the character code [c] by the first character map found
    in the order POV-Ray searches them (Macintosh, Microsoft Unicode, Unicode, Microsoft symbols;
    with [~utf8:true] Unicode, Microsoft Unicode, Macintosh, Microsoft symbols; only the platform is
    compared), formats 0, 4 (retrying 0xF000 + c for codes below 256) and 6; 0 when none has it. *)

val outline : t -> int -> char_code:int -> (Glyph.outline * int, string) result
(** [outline f g ~char_code] is the outline of glyph [g] and the glyph whose metrics it uses; a
    space ([char_code] 32) has none. *)

val layout : ?utf8:bool -> t -> int array -> offset:Vec.t -> ((Glyph.outline * Vec.t) list, string) result
(** [layout ?utf8 f codes ~offset] is each character code of [codes] as its outline and the
    translation placing it: the first glyph's left edge at x = 0, each next one advanced by the
    advance width and kerning, plus [offset] after every character (POV-Ray's ProcessNewTTF; the
    translation's z is always 0, the offset's z is not used). *)
