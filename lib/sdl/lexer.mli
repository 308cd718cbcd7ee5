(** The lexer: scene text to an array of located tokens (POVRAY-3.7 §11.1). *)

val tokenize : file:string -> string -> Token.t array
(** [tokenize ~file text] is every token of [text] followed by [Eof]. Nested comments are skipped, a
    UTF-8 byte-order mark is ignored. Raises [Error.Scene_error] on an unterminated comment or string
    or a character that cannot start a token. *)
