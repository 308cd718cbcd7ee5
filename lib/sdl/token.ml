(* Tokens of the scene language, and how a message names one. *)

type kind =
  | Num of float
  | Str of string
  | Ident of string
  | Directive of string
  | LBrace | RBrace | LParen | RParen | Lt | Gt | LBracket | RBracket
  | Comma | Semi | Plus | Minus | Star | Slash | Dot | Eq | Ne | Le | Ge
  | Bang | Amp | Bar | Quest | Colon
  | Hash  (* a '#' with no directive name after it, which the reader ignores *)
  | Eof

type t = { kind : kind; loc : Loc.t }

let describe = function
  | Num f -> Printf.sprintf "number %g" f
  | Str s -> Printf.sprintf "string \"%s\"" (if String.length s > 40 then String.sub s 0 40 ^ "…" else s)
  | Ident s -> Printf.sprintf "'%s'" (if String.length s > 40 then String.sub s 0 40 ^ "…" else s)
  | Directive s -> Printf.sprintf "'#%s'" s
  | LBrace -> "'{'" | RBrace -> "'}'" | LParen -> "'('" | RParen -> "')'"
  | Lt -> "'<'" | Gt -> "'>'" | LBracket -> "'['" | RBracket -> "']'"
  | Comma -> "','" | Semi -> "';'" | Plus -> "'+'" | Minus -> "'-'" | Star -> "'*'"
  | Slash -> "'/'" | Dot -> "'.'" | Eq -> "'='" | Ne -> "'!='" | Le -> "'<='" | Ge -> "'>='"
  | Bang -> "'!'" | Amp -> "'&'" | Bar -> "'|'" | Quest -> "'?'" | Colon -> "':'" | Hash -> "'#'"
  | Eof -> "end of file"
