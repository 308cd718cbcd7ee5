open Token

let is_digit c = c >= '0' && c <= '9'
let is_hex c = is_digit c || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')
let is_ident_start c = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c = '_'
let is_ident c = is_ident_start c || is_digit c

let tokenize ~file text =
  let len = String.length text in
  let toks = ref [] in
  let line = ref 1 and bol = ref 0 in
  let loc_at pos = { Loc.file; line = !line; col = pos - !bol + 1 } in
  let newline pos = incr line; bol := pos + 1 in
  let push kind loc = toks := { kind; loc } :: !toks in
  (* Skip a byte-order mark. *)
  let start = if len >= 3 && String.sub text 0 3 = "\xEF\xBB\xBF" then 3 else 0 in
  bol := start;
  let rec skip_block pos depth open_locs =
    (* Inside a /* */ comment; comments nest (§11.1). *)
    if pos >= len then Error.raise_at (List.hd open_locs) "unterminated comment: '/*' has no matching '*/'"
    else
      let c = text.[pos] in
      if c = '\n' then (newline pos; skip_block (pos + 1) depth open_locs)
      else if c = '*' && pos + 1 < len && text.[pos + 1] = '/' then
        if depth = 1 then pos + 2 else skip_block (pos + 2) (depth - 1) (List.tl open_locs)
      else if c = '/' && pos + 1 < len && text.[pos + 1] = '*' then
        skip_block (pos + 2) (depth + 1) (loc_at pos :: open_locs)
      else skip_block (pos + 1) depth open_locs
  in
  let lex_string pos =
    (* pos is just after the opening quote *)
    let loc = loc_at (pos - 1) in
    let buf = Buffer.create 16 in
    let rec go p =
      if p >= len || text.[p] = '\n' then Error.raise_at loc "unterminated string: missing closing '\"'"
      else
        match text.[p] with
        | '"' -> p + 1
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
            | 'u' when p + 5 < len && String.for_all is_hex (String.sub text (p + 2) 4) ->
                (* \uXXXX: a Unicode code point, kept as UTF-8 *)
                let cp = int_of_string ("0x" ^ String.sub text (p + 2) 4) in
                Buffer.add_utf_8_uchar buf (if Uchar.is_valid cp then Uchar.of_int cp else Uchar.rep)
            | _ -> Buffer.add_char buf '\\'; Buffer.add_char buf e);
            go (if e = 'u' && p + 5 < len && String.for_all is_hex (String.sub text (p + 2) 4) then p + 6 else p + 2)
        | c -> Buffer.add_char buf c; go (p + 1)
    in
    let p = go pos in
    push (Str (Buffer.contents buf)) loc;
    p
  in
  let lex_number pos =
    let p = ref pos in
    while !p < len && is_digit text.[!p] do incr p done;
    if !p < len && text.[!p] = '.' && not (!p + 1 < len && is_ident_start text.[!p + 1] && text.[!p + 1] <> 'e' && text.[!p + 1] <> 'E') then begin
      incr p;
      while !p < len && is_digit text.[!p] do incr p done
    end;
    if !p < len && (text.[!p] = 'e' || text.[!p] = 'E') then begin
      let q = ref (!p + 1) in
      if !q < len && (text.[!q] = '+' || text.[!q] = '-') then incr q;
      if !q < len && is_digit text.[!q] then begin
        p := !q;
        while !p < len && is_digit text.[!p] do incr p done
      end
    end;
    let s = String.sub text pos (!p - pos) in
    let f = match float_of_string_opt s with Some f -> f | None -> Error.raise_at (loc_at pos) "malformed number '%s'" s in
    push (Num f) (loc_at pos);
    !p
  in
  (* End of file is reported just after the last visible character, so a message about a missing
     '}' shows the line where the text stops. *)
  let eof_loc () =
    let p = ref (len - 1) in
    while !p >= start && (match text.[!p] with ' ' | '\t' | '\r' | '\n' -> true | _ -> false) do decr p done;
    if !p < start then { Loc.file; line = 1; col = 1 }
    else
      let line = ref 1 and bol = ref start in
      for i = start to !p do if text.[i] = '\n' then (incr line; bol := i + 1) done;
      { Loc.file; line = !line; col = !p - !bol + 2 }
  in
  let rec go pos =
    if pos >= len then push Eof (eof_loc ())
    else
      let c = text.[pos] in
      let next = pos + 1 in
      let single k = push k (loc_at pos); go next in
      let two k = push k (loc_at pos); go (pos + 2) in
      let peek_is ch = next < len && text.[next] = ch in
      match c with
      | '\n' -> newline pos; go next
      | ' ' | '\t' | '\r' | '\012' | '\011' | '\026' -> go next
      | '/' when peek_is '/' ->
          let p = ref next in
          while !p < len && text.[!p] <> '\n' do incr p done;
          go !p
      | '/' when peek_is '*' -> go (skip_block (pos + 2) 1 [ loc_at pos ])
      | '"' -> go (lex_string next)
      | '0' .. '9' -> go (lex_number pos)
      | '.' when next < len && is_digit text.[next] -> go (lex_number pos)
      | '#' ->
          let p = ref next in
          while !p < len && (text.[!p] = ' ' || text.[!p] = '\t') do incr p done;
          let s = !p in
          while !p < len && is_ident text.[!p] do incr p done;
          if !p = s then Error.raise_at (loc_at pos) "'#' must be followed by a directive name";
          push (Directive (String.sub text s (!p - s))) (loc_at pos);
          go !p
      | c when is_ident_start c ->
          let p = ref next in
          while !p < len && is_ident text.[!p] do incr p done;
          push (Ident (String.sub text pos (!p - pos))) (loc_at pos);
          go !p
      | '{' -> single LBrace | '}' -> single RBrace
      | '(' -> single LParen | ')' -> single RParen
      | '[' -> single LBracket | ']' -> single RBracket
      | ',' -> single Comma | ';' -> single Semi
      | '+' -> single Plus | '-' -> single Minus | '*' -> single Star | '/' -> single Slash
      | '.' -> single Dot | '=' -> single Eq
      | '!' when peek_is '=' -> two Ne
      | '!' -> single Bang
      | '<' when peek_is '=' -> two Le
      | '<' -> single Lt
      | '>' when peek_is '=' -> two Ge
      | '>' -> single Gt
      | '&' -> single Amp | '|' -> single Bar | '?' -> single Quest | ':' -> single Colon
      | c ->
          let shown = if Char.code c >= 32 && Char.code c < 127 then Printf.sprintf "'%c'" c else Printf.sprintf "byte 0x%02X" (Char.code c) in
          Error.raise_at (loc_at pos) "unexpected character %s" shown
  in
  go start;
  Array.of_list (List.rev !toks)
