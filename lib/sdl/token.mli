(** Tokens of the scene language, each with the location of its first character. *)

type kind =
  | Num of float
  | Str of string
  | Ident of string  (** keywords and identifiers alike *)
  | Directive of string  (** [#declare] is [Directive "declare"] *)
  | LBrace | RBrace | LParen | RParen | Lt | Gt | LBracket | RBracket
  | Comma | Semi | Plus | Minus | Star | Slash | Dot | Eq | Ne | Le | Ge
  | Bang | Amp | Bar | Quest | Colon
  | Hash  (** a ['#'] with no directive name after it (on its line), which the reader ignores *)
  | Eof

type t = { kind : kind; loc : Loc.t }

val describe : kind -> string
(** [describe k] is how a message names the token, e.g. "'{'" or "identifier 'Foo'". *)
