(* Errors and warnings in scenes, and their one printed form: the message, the source line with a
   caret under the column, the notes. *)

type kind = Scene | Limit | Access
type t = { loc : Loc.t; msg : string; notes : (Loc.t * string) list; kind : kind }

exception Scene_error of t

let raise_kind kind loc fmt = Printf.ksprintf (fun msg -> raise (Scene_error { loc; msg; notes = []; kind })) fmt
let raise_at loc fmt = raise_kind Scene loc fmt
let limit_at loc fmt = raise_kind Limit loc fmt
let access_at loc fmt = raise_kind Access loc fmt
let limit_error loc msg = { loc; msg; notes = []; kind = Limit }
let warning loc msg = { loc; msg; notes = []; kind = Scene }
let raise_notes loc notes msg = raise (Scene_error { loc; msg; notes; kind = Scene })

(* The [n]th line (1-based) of [text], without its line end, lines ending as the lexer counts them. *)
let nth_line text n =
  let text = Line_ends.normalise text in
  let len = String.length text in
  let rec find_start pos line =
    if line = n then Some pos
    else
      match String.index_from_opt text pos '\n' with
      | Some i when i + 1 <= len -> find_start (i + 1) (line + 1)
      | _ -> None
  in
  match find_start 0 1 with
  | None -> None
  | Some start ->
      let stop = match String.index_from_opt text start '\n' with Some i -> i | None -> len in
      Some (String.sub text start (stop - start))

(* The length of the valid UTF-8 sequence starting at [i] of [s], or 0. *)
let utf8_length s i =
  let n = String.length s in
  let cont k = i + k < n && Char.code s.[i + k] land 0xC0 = 0x80 in
  match Char.code s.[i] with
  | c when c < 0x80 -> 1
  | c when c >= 0xC2 && c < 0xE0 && cont 1 -> 2
  | c when c >= 0xE0 && c < 0xF0 && cont 1 && cont 2 -> 3
  | c when c >= 0xF0 && c < 0xF5 && cont 1 && cont 2 && cont 3 -> 4
  | _ -> 0

(* [line] as it can be shown on a terminal, from byte [first] for at most [width] characters:
   control characters and bytes that are not UTF-8 become '?', tabs stay (so the caret lines up).
   Also the pad that puts a caret under byte [col] (0-based). *)
let display line ~first ~width ~col =
  let b = Buffer.create 256 and pad = Buffer.create 64 in
  let n = String.length line in
  let rec go i shown =
    if i < n && shown < width then begin
      let k = utf8_length line i in
      let c = line.[i] in
      let text = if k = 0 || (k = 1 && (c < ' ' || c = '\127') && c <> '\t') then "?" else String.sub line i k in
      Buffer.add_string b text;
      if i < col then Buffer.add_char pad (if c = '\t' then '\t' else ' ');
      go (i + max k 1) (shown + 1)
    end
    else i
  in
  let stop = go first 0 in
  (Buffer.contents b, Buffer.contents pad, stop < n)

let excerpt ~source (loc : Loc.t) =
  if loc.line <= 0 then ""
  else
    match source loc.file with
    | None -> ""
    | Some text -> (
        match nth_line text loc.line with
        | None -> ""
        | Some line ->
            (* a line longer than 200 bytes is shown as 160 characters around the column *)
            let col = max 0 (min (loc.col - 1) (String.length line)) in
            let first = if String.length line <= 200 || col < 120 then 0 else col - 80 in
            (* start on a character, not inside one *)
            let first = let rec back i = if i > 0 && Char.code line.[i] land 0xC0 = 0x80 then back (i - 1) else i in back first in
            let shown, pad, cut = display line ~first ~width:(if String.length line <= 200 then 200 else 160) ~col in
            let lead = if first > 0 then "…" else "" in
            let number = Printf.sprintf "%5d" loc.line in
            Printf.sprintf "%s | %s%s%s\n%s | %s%s^\n" number lead shown (if cut then "…" else "")
              (String.make (String.length number) ' ') (if first > 0 then " " else "") pad)

let render ~source ~kind e =
  let head =
    if e.loc.line > 0 then Printf.sprintf "%s: %s: %s\n" (Loc.to_string e.loc) kind e.msg
    else if e.loc.file <> "" then Printf.sprintf "%s: %s: %s\n" e.loc.file kind e.msg
    else Printf.sprintf "%s: %s\n" kind e.msg
  in
  let note (l, m) =
    if l.Loc.line <= 0 then Printf.sprintf "note: %s\n" m
    else Printf.sprintf "%s: note: %s\n" (Loc.to_string l) m
  in
  head ^ excerpt ~source e.loc ^ String.concat "" (List.map note e.notes)
