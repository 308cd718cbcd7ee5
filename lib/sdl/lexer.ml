(* The lexer: scene text to located tokens, read on demand, and the fast path that reads a vector
   of plain numbers straight from the text (docs/povray-rules.md §11.1). *)

open Token

let is_digit c = c >= '0' && c <= '9'
let is_hex c = is_digit c || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')
let is_ident_start c = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c = '_'
let is_ident c = is_ident_start c || is_digit c

(* The lexer reads on demand, one token at a time, so a 40 MB mesh never exists as a token array. *)
type t = {
  file : string;
  text : string;
  len : int;
  start : int;  (* after a byte-order mark *)
  mutable pos : int;
  mutable line : int;
  mutable bol : int;  (* offset where the current line begins *)
}

let create ~file text =
  let text = Line_ends.normalise text in
  let len = String.length text in
  let start = if len >= 3 && String.sub text 0 3 = "\xEF\xBB\xBF" then 3 else 0 in
  { file; text; len; start; pos = start; line = 1; bol = start }

let loc_at lx pos = { Loc.file = lx.file; line = lx.line; col = pos - lx.bol + 1 }
let newline lx pos = lx.line <- lx.line + 1; lx.bol <- pos + 1

(* End of file is reported just after the last visible character, so a message about a missing
   '}' shows the line where the text stops. *)
let eof_loc lx =
  let text = lx.text in
  let p = ref (lx.len - 1) in
  while !p >= lx.start && (match text.[!p] with ' ' | '\t' | '\r' | '\n' -> true | _ -> false) do decr p done;
  if !p < lx.start then { Loc.file = lx.file; line = 1; col = 1 }
  else
    let line = ref 1 and bol = ref lx.start in
    for i = lx.start to !p do if text.[i] = '\n' then (incr line; bol := i + 1) done;
    { Loc.file = lx.file; line = !line; col = !p - !bol + 2 }

(* Inside a /* */ comment from [pos]; comments nest (§11.1). Returns the offset after the comment. *)
let skip_block lx pos open_loc =
  let text = lx.text and len = lx.len in
  let rec go pos depth opens =
    if pos >= len then Error.raise_at (List.hd opens) "unterminated comment: '/*' has no matching '*/'"
    else
      let c = String.unsafe_get text pos in
      if c = '\n' then (newline lx pos; go (pos + 1) depth opens)
      else if c = '*' && pos + 1 < len && text.[pos + 1] = '/' then
        if depth = 1 then pos + 2 else go (pos + 2) (depth - 1) (List.tl opens)
      else if c = '/' && pos + 1 < len && text.[pos + 1] = '*' then go (pos + 2) (depth + 1) (loc_at lx pos :: opens)
      else go (pos + 1) depth opens
  in
  go pos 1 [ open_loc ]

(* POV-Ray refuses a token (identifier, string, number) of 256 characters or more, counted as
   written (escapes count as two). *)
let max_token = 255

let check_length lx pos n what =
  if n > max_token then
    Error.raise_at (loc_at lx pos) "this %s is %d characters long; POV-Ray allows at most %d" what n max_token

(* A string from just after its opening quote; returns the token and the offset after it. A
   line break inside the quotes is part of the string, as one '\n' whatever the file's line ends
   (POV-Ray's Parse_String_Literal in tokenize.cpp reads to the closing quote, and its text stream
   turns CR LF, LF CR and a lone CR into one '\n', as [create] does ({!Line_ends}): shapes3.inc's
   #warning at line 881 spans three lines); only the end of the file, or a '\' just before a line
   break, leaves it unterminated. *)
let lex_string lx pos =
  let text = lx.text and len = lx.len in
  let loc = loc_at lx (pos - 1) in
  let buf = Buffer.create 16 in
  (* characters as POV-Ray counts them for its length limit: as written, a line end as one *)
  let written = ref 0 in
  let unicode_at p = p + 5 < len && String.for_all is_hex (String.sub text (p + 2) 4) in
  let rec go p =
    if p >= len then Error.raise_at loc "unterminated string: missing closing '\"'"
    else
      match text.[p] with
      | '"' -> p + 1
      | '\n' -> Buffer.add_char buf '\n'; incr written; newline lx p; go (p + 1)
      | '\\' when p + 1 < len && text.[p + 1] = '\n' ->
          Error.raise_at (loc_at lx p) "unterminated string: a '\\' ends the line (POV-Ray refuses it; a backslash is written '\\\\')"
      | '\\' when p + 1 < len ->
          let e = text.[p + 1] in
          (match e with
          | 'n' -> Buffer.add_char buf '\n'
          | 't' -> Buffer.add_char buf '\t'
          | 'r' -> Buffer.add_char buf '\r'
          | 'a' -> Buffer.add_char buf '\007'
          | 'b' -> Buffer.add_char buf '\b'
          | 'f' -> Buffer.add_char buf '\012'
          | 'v' -> Buffer.add_char buf '\011'
          | '0' -> Buffer.add_char buf '\000'
          | '\\' | '"' | '\'' -> Buffer.add_char buf e
          | 'u' when unicode_at p ->
              (* \uXXXX: a Unicode code point, kept as UTF-8 *)
              let cp = int_of_string ("0x" ^ String.sub text (p + 2) 4) in
              Buffer.add_utf_8_uchar buf (if Uchar.is_valid cp then Uchar.of_int cp else Uchar.rep)
          | _ -> Buffer.add_char buf '\\'; Buffer.add_char buf e);
          let n = if e = 'u' && unicode_at p then 6 else 2 in
          written := !written + n;
          go (p + n)
      | c -> Buffer.add_char buf c; incr written; go (p + 1)
  in
  let p = go pos in
  if !written > max_token then
    Error.raise_at loc "this string is %d characters long; POV-Ray allows at most %d" !written max_token;
  ({ kind = Str (Buffer.contents buf); loc }, p)

(* A number: digits, an optional fraction, an optional exponent (§11.1). *)
(* Exact powers of ten: a mantissa below 2^53 divided by one of these is correctly rounded. *)
let pow10 = Array.init 23 (fun i -> float_of_string ("1e" ^ string_of_int i))

let lex_number lx pos =
  let text = lx.text and len = lx.len in
  let p = ref pos in
  (* the digits are also accumulated for the fast path of plain decimals *)
  let mant = ref 0 and digits = ref 0 and frac = ref 0 in
  let digit c = mant := (!mant * 10) + (Char.code c - 48); incr digits in
  while !p < len && is_digit text.[!p] do digit text.[!p]; incr p done;
  (* "1.x" is not a number followed by ".x": a '.' followed by a letter other than e/E stays a dot *)
  if !p < len && text.[!p] = '.'
     && not (!p + 1 < len && is_ident_start text.[!p + 1] && text.[!p + 1] <> 'e' && text.[!p + 1] <> 'E')
  then begin
    incr p;
    while !p < len && is_digit text.[!p] do digit text.[!p]; incr frac; incr p done
  end;
  if !digits <= 15 && !frac <= 22 && not (!p < len && (text.[!p] = 'e' || text.[!p] = 'E')) then
    (* plain decimal with few digits: one correctly rounded division, as strtod would give *)
    ({ kind = Num (float_of_int !mant /. pow10.(!frac)); loc = loc_at lx pos }, !p)
  else begin
  if !p < len && (text.[!p] = 'e' || text.[!p] = 'E') then begin
    let q = ref (!p + 1) in
    if !q < len && (text.[!q] = '+' || text.[!q] = '-') then incr q;
    if !q < len && is_digit text.[!q] then begin
      p := !q;
      while !p < len && is_digit text.[!p] do incr p done
    end
  end;
  let s = String.sub text pos (!p - pos) in
  let f = match float_of_string_opt s with Some f -> f | None -> Error.raise_at (loc_at lx pos) "malformed number '%s'" s in
  ({ kind = Num f; loc = loc_at lx pos }, !p)
  end

(* The mesh fast path: the lists of a mesh hold millions of vectors like "<-1.25, 0.5, 3>", and
   reading each through tokens and expressions costs far more than the numbers are worth. From just
   after a '<', [scan_vector3] reads three plain decimals (an optional sign, digits, an optional
   fraction: the numbers [lex_number] converts by one division) separated by commas, and the '>'
   after them, when the next character is ',' or '}' (so nothing could continue an expression). It
   then stores the numbers, moves past the '>' and returns true; for anything else it moves
   nothing and returns false, and the caller reads the vector the general way. *)
let rec skip_ws lx p =
  if p >= lx.len then p
  else
    match String.unsafe_get lx.text p with
    | ' ' | '\t' | '\r' | '\000' -> skip_ws lx (p + 1)
    | '\n' -> newline lx p; skip_ws lx (p + 1)
    | _ -> p

(* a plain decimal at [p] into out.(i): the position after it, or −1 *)
let scan_number lx p (out : float array) i =
  let text = lx.text and len = lx.len in
  let p = skip_ws lx p in
  let neg = p < len && String.unsafe_get text p = '-' in
  let p = if p < len && (neg || String.unsafe_get text p = '+') then skip_ws lx (p + 1) else p in
  let q = ref p and mant = ref 0 and digits = ref 0 and frac = ref 0 in
  while !q < len && is_digit (String.unsafe_get text !q) do
    mant := (!mant * 10) + (Char.code (String.unsafe_get text !q) - 48); incr digits; incr q
  done;
  if !q < len && String.unsafe_get text !q = '.' then begin
    incr q;
    while !q < len && is_digit (String.unsafe_get text !q) do
      mant := (!mant * 10) + (Char.code (String.unsafe_get text !q) - 48); incr digits; incr frac; incr q
    done
  end;
  let e = !q < len && (match String.unsafe_get text !q with 'e' | 'E' | '_' | 'a' .. 'd' | 'f' .. 'z' | 'A' .. 'D' | 'F' .. 'Z' | '.' -> true | _ -> false) in
  if !digits = 0 || !digits > 15 || !frac > 22 || e then -1
  else begin
    let f = float_of_int !mant /. Array.unsafe_get pow10 !frac in
    out.(i) <- (if neg then -.f else f);
    !q
  end

let scan_vector3 lx (out : float array) =
  let line = lx.line and bol = lx.bol in
  let text = lx.text and len = lx.len in
  let sep p c = let p = skip_ws lx p in if p < len && String.unsafe_get text p = c then p + 1 else -1 in
  let ok =
    let p = scan_number lx lx.pos out 0 in
    let p = if p < 0 then -1 else sep p ',' in
    let p = if p < 0 then -1 else scan_number lx p out 1 in
    let p = if p < 0 then -1 else sep p ',' in
    let p = if p < 0 then -1 else scan_number lx p out 2 in
    let p = if p < 0 then -1 else sep p '>' in
    if p < 0 then false
    else begin
      (* what follows must end the item (looked at without counting lines: [next] counts them) *)
      let q = ref p in
      while !q < len && (match String.unsafe_get text !q with ' ' | '\t' | '\r' | '\n' -> true | _ -> false) do incr q done;
      let q = !q in
      if q < len && (match String.unsafe_get text q with ',' | '}' -> true | _ -> false) then begin
        lx.pos <- p; true
      end
      else false
    end
  in
  if not ok then begin lx.line <- line; lx.bol <- bol end;
  ok

(* POV-Ray's directive names (Parse_Directive in tokenize.cpp). *)
let directive_names =
  [ "declare"; "local"; "undef"; "version"; "include"; "if"; "ifdef"; "ifndef"; "elseif"; "else"; "end"; "while";
    "for"; "switch"; "case"; "range"; "break"; "macro"; "debug"; "warning"; "error"; "default"; "fopen"; "fclose";
    "read"; "write"; "render"; "statistics" ]

let directive_table =
  let h = Hashtbl.create 64 in
  List.iter (fun d -> Hashtbl.replace h d ()) directive_names;
  h

let is_directive_name s = Hashtbl.mem directive_table s

(* From [p], past white space (lines counted) and comments: the offset of the next token. *)
let rec skip_blank lx p =
  let text = lx.text and len = lx.len in
  if p >= len then p
  else
    match String.unsafe_get text p with
    | '\n' -> newline lx p; skip_blank lx (p + 1)
    | ' ' | '\t' | '\r' | '\012' | '\011' | '\026' | '\000' -> skip_blank lx (p + 1)
    | '/' when p + 1 < len && text.[p + 1] = '/' ->
        (match String.index_from_opt text p '\n' with Some q -> skip_blank lx q | None -> len)
    | '/' when p + 1 < len && text.[p + 1] = '*' -> skip_blank lx (skip_block lx (p + 2) (loc_at lx p))
    | _ -> p

let next lx =
  let text = lx.text and len = lx.len in
  let rec go pos =
    if pos >= len then begin
      lx.pos <- len;
      { kind = Eof; loc = eof_loc lx }
    end
    else
      let c = String.unsafe_get text pos in
      let tok k n = lx.pos <- pos + n; { kind = k; loc = loc_at lx pos } in
      let peek_is ch = pos + 1 < len && text.[pos + 1] = ch in
      match c with
      | '\n' -> newline lx pos; go (pos + 1)
      | ' ' | '\t' | '\r' | '\012' | '\011' | '\026' | '\000' -> go (pos + 1)
      | '/' when peek_is '/' ->
          let p = ref (pos + 1) in
          while !p < len && text.[!p] <> '\n' do incr p done;
          go !p
      | '/' when peek_is '*' -> go (skip_block lx (pos + 2) (loc_at lx pos))
      | '"' -> let t, p = lex_string lx (pos + 1) in lx.pos <- p; t
      | '0' .. '9' -> let t, p = lex_number lx pos in check_length lx pos (p - pos) "number"; lx.pos <- p; t
      | '.' when pos + 1 < len && is_digit text.[pos + 1] -> let t, p = lex_number lx pos in check_length lx pos (p - pos) "number"; lx.pos <- p; t
      | '#' ->
          (* POV-Ray reads the token after a '#', wherever it is (Parse_Directive in tokenize.cpp):
             a directive name on a later line or after a comment is still the directive. Any other
             token is left to be read as usual after a [Hash]. *)
          let loc = loc_at lx pos and line = lx.line and bol = lx.bol in
          let s = skip_blank lx (pos + 1) in
          let p = ref s in
          while !p < len && is_ident text.[!p] do incr p done;
          let name = String.sub text s (!p - s) in
          if is_directive_name name then begin lx.pos <- !p; { kind = Directive name; loc } end
          else begin lx.line <- line; lx.bol <- bol; lx.pos <- pos + 1; { kind = Hash; loc } end
      | c when is_ident_start c ->
          let p = ref (pos + 1) in
          while !p < len && is_ident text.[!p] do incr p done;
          check_length lx pos (!p - pos) "identifier";
          tok (Ident (String.sub text pos (!p - pos))) (!p - pos)
      | '{' -> tok LBrace 1 | '}' -> tok RBrace 1
      | '(' -> tok LParen 1 | ')' -> tok RParen 1
      | '[' -> tok LBracket 1 | ']' -> tok RBracket 1
      | ',' -> tok Comma 1 | ';' -> tok Semi 1
      | '+' -> tok Plus 1 | '-' -> tok Minus 1 | '*' -> tok Star 1 | '/' -> tok Slash 1
      | '.' -> tok Dot 1 | '=' -> tok Eq 1
      | '!' when peek_is '=' -> tok Ne 2
      | '!' -> tok Bang 1
      | '<' when peek_is '=' -> tok Le 2
      | '<' -> tok Lt 1
      | '>' when peek_is '=' -> tok Ge 2
      | '>' -> tok Gt 1
      | '&' -> tok Amp 1 | '|' -> tok Bar 1 | '?' -> tok Quest 1 | ':' -> tok Colon 1
      | c ->
          let shown = if Char.code c >= 32 && Char.code c < 127 then Printf.sprintf "'%c'" c else Printf.sprintf "byte 0x%02X" (Char.code c) in
          Error.raise_at (loc_at lx pos) "unexpected character %s" shown
  in
  go lx.pos

let tokenize ~file text =
  let lx = create ~file text in
  let rec all acc = match next lx with { kind = Eof; _ } as t -> List.rev (t :: acc) | t -> all (t :: acc) in
  Array.of_list (all [])

(* Positions to come back to: a #while loop re-reads its condition, a macro body starts where it was
   written. A mark is taken between tokens. *)
type mark = { m_pos : int; m_line : int; m_bol : int }

let mark lx = { m_pos = lx.pos; m_line = lx.line; m_bol = lx.bol }
let reset lx m = lx.pos <- m.m_pos; lx.line <- m.m_line; lx.bol <- m.m_bol
let file lx = lx.file

(* A second reader of the same text, starting at [m] (a macro body). *)
let at lx m = { lx with pos = m.m_pos; line = m.m_line; bol = m.m_bol }

(* The next character that is not blank or inside a comment, without moving: whether an argument
   that is a bare identifier ends there (',' or ')'). *)
let next_char lx =
  let text = lx.text and len = lx.len in
  let rec go p =
    if p >= len then None
    else
      match text.[p] with
      | ' ' | '\t' | '\r' | '\n' | '\012' | '\011' | '\000' -> go (p + 1)
      | '/' when p + 1 < len && text.[p + 1] = '/' ->
          (match String.index_from_opt text p '\n' with Some q -> go q | None -> None)
      | '/' when p + 1 < len && text.[p + 1] = '*' ->
          let rec close p depth =
            if p + 1 >= len then len
            else if text.[p] = '*' && text.[p + 1] = '/' then (if depth = 1 then p + 2 else close (p + 2) (depth - 1))
            else if text.[p] = '/' && text.[p + 1] = '*' then close (p + 2) (depth + 1)
            else close (p + 1) depth
          in
          go (close (p + 2) 1)
      | c -> Some c
  in
  go lx.pos
