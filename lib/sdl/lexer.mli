(** The lexer: scene text to located tokens, read on demand (docs/povray-rules.md §11.1). *)

type t
(** A lexer over one text. *)

val create : file:string -> string -> t
(** [create ~file text] starts reading [text] (named [file] in locations); a UTF-8 byte-order mark
    is skipped. *)

val next : t -> Token.t
(** [next lx] is the next token, [Eof] at the end (and again after it). Nested comments are skipped.
    A '#' followed (after white space and comments, line breaks included) by a directive name is
    one [Directive] token located at the '#'; any other '#' is a [Hash] token, and what follows it
    is read as the next token. Raises [Error.Scene_error] on an unterminated comment or string or a
    character that cannot start a token. *)

val directive_names : string list
(** [directive_names] are POV-Ray's directive names (what may follow a '#'). *)

val is_directive_name : string -> bool
(** [is_directive_name s] tells whether [s] is one of [directive_names]. *)

val scan_vector3 : t -> float array -> bool
(** [scan_vector3 lx out], just after a '<': if the text goes on with three plain decimals
    (optional sign, digits, optional fraction) separated by commas, then '>', then (after white
    space) ',' or '}', stores the three numbers in [out.(0..2)] — the values [next] would give —,
    moves past the '>' and is true. Otherwise it moves nothing and is false. *)

val tokenize : file:string -> string -> Token.t array
(** [tokenize ~file text] is every token of [text] followed by [Eof] (for tests and tools). *)

(** A position between two tokens. *)
type mark

val mark : t -> mark
(** [mark lx] is the position [lx] reads from next. *)

val reset : t -> mark -> unit
(** [reset lx m] makes [lx] read from [m] again (a [#while] re-reading its condition). *)

val at : t -> mark -> t
(** [at lx m] is a new reader of [lx]'s text starting at [m] (a macro body). *)

val file : t -> string
(** [file lx] is the file name the locations of [lx] carry. *)

val next_char : t -> char option
(** [next_char lx] is the next character that is neither blank nor in a comment, without moving. *)
