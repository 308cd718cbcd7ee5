(** The reader of a declared spline, [spline { … }] (docs/povray-rules.md §11.5; Parse_Spline of
    parser/express.cpp). *)

val read_block_with : named:(Reader.st -> string -> Spline.t option) -> Reader.st -> Spline.t
(** [read_block_with ~named st] reads the block after the [spline] keyword, from its '{' to its
    '}': [[SPLINE_ID] [linear_spline | quadratic_spline | cubic_spline | natural_spline]…
    TIME [,] VALUE [,] …]. [named st s] is the spline the identifier [s] names, if it names one:
    the block is then a copy of it, of its kind unless a type keyword follows, with the entries
    written added ({!Spline.add}). Any number of type keywords may come before the first entry,
    the last one counting (a keyword after an entry is not one and stops the block, as any token
    that cannot start a float does); the default is [linear_spline]. A time is a float; a value a
    float, vector or colour (a float counts as two terms); the commas are optional. A block with
    no entry and no spline to copy is POV-Ray's error "Spline must have at least one entry.". *)

val read_block : Reader.st -> Spline.t
(** [read_block st] is [read_block_with] where no identifier names a spline. *)
