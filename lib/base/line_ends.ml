(* Line ends as POV-Ray's text stream reads them. *)

let normalise text =
  if not (String.contains text '\r') then text
  else begin
    let len = String.length text in
    let b = Buffer.create len in
    (* a line end at [p]: the offset after it (its second character, if the pair is CR LF or
       LF CR, belongs to it) *)
    let rec go p =
      if p < len then
        match text.[p] with
        | ('\n' | '\r') as c ->
            Buffer.add_char b '\n';
            let other = if c = '\n' then '\r' else '\n' in
            go (if p + 1 < len && text.[p + 1] = other then p + 2 else p + 1)
        | c -> Buffer.add_char b c; go (p + 1)
    in
    go 0;
    Buffer.contents b
  end
