(** Expressions (docs/povray-rules.md §11.2): floats, vectors, colours, strings, the built-in functions and
    the transformations. *)

val function_names : string list
(** [function_names] are the built-in functions povml reads. *)

val object_set : unit Reader.Names.t
(** [object_set] are the keywords that start an object povml reads. *)

val is_colour_start : Reader.st -> bool
(** [is_colour_start st] tells whether a colour (keyword or colour identifier) comes next. *)

val truth : float -> bool
(** [truth x] is POV-Ray's truth: |x| > 1e-10. *)

val c_int : float -> float
(** [c_int x] is C's [(int)x] on x86: [x] truncated toward zero, and -2147483648 for NaN and what
    does not fit in 32 bits. *)

val srgb_decode : assumed_gamma:float -> float -> float
(** [srgb_decode ~assumed_gamma x] is the sRGB term [x] in the working colour space of
    [assumed_gamma], in single precision, as POV-Ray 3.7 reads the terms of [srgb] colours. *)

val parse_expr : Reader.st -> Value.t
(** [parse_expr st] reads an arithmetic expression (no relational operators outside parentheses). *)

val parse_full : Reader.st -> Value.t
(** [parse_full st] reads a full expression: ?:, & |, comparisons and arithmetic. *)

val parse_primary : Reader.st -> Value.t
(** [parse_primary st] reads one operand without looking past it. *)

val parse_defined_arg : Reader.st -> bool
(** [parse_defined_arg st] reads the identifier of defined()/#ifdef and tells whether it is defined. *)

val parse_float : Reader.st -> float
(** [parse_float st] reads a float expression. *)

val parse_vector : Reader.st -> Vec.t
(** [parse_vector st] reads a vector expression promoted to three terms. *)

val parse_colour : Reader.st -> Colour.t
(** [parse_colour st] reads a colour in any of its syntaxes. *)

val parse_rgb : Reader.st -> string -> Rgb.t
(** [parse_rgb st what] reads a colour where only red, green and blue count. *)

val float_follows : Reader.st -> bool
(** [float_follows st] tells whether a float expression comes next (for optional values). *)

val parse_bool_opt : Reader.st -> bool
(** [parse_bool_opt st] reads an optional boolean, true when absent. *)

val parse_op : Reader.st -> Place.op
(** [parse_op st] reads one of translate, rotate, scale, matrix, transform. *)

val parse_transform : Reader.st -> Transform.t
(** [parse_transform st] reads a transform block or identifier (after the keyword). *)
