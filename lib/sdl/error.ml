type kind = Scene | Limit | Access
type t = { loc : Loc.t; msg : string; notes : (Loc.t * string) list; kind : kind }

exception Scene_error of t

let raise_kind kind loc fmt = Printf.ksprintf (fun msg -> raise (Scene_error { loc; msg; notes = []; kind })) fmt
let raise_at loc fmt = raise_kind Scene loc fmt
let limit_at loc fmt = raise_kind Limit loc fmt
let access_at loc fmt = raise_kind Access loc fmt
let warning loc msg = { loc; msg; notes = []; kind = Scene }
let raise_notes loc notes msg = raise (Scene_error { loc; msg; notes; kind = Scene })

(* The [n]th line (1-based) of [text], without its line end. *)
let nth_line text n =
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
      let stop = if stop > start && text.[stop - 1] = '\r' then stop - 1 else stop in
      Some (String.sub text start (stop - start))

let excerpt ~source (loc : Loc.t) =
  if loc.line <= 0 then ""
  else
    match source loc.file with
    | None -> ""
    | Some text -> (
        match nth_line text loc.line with
        | None -> ""
        | Some line ->
            let line = if String.length line > 200 then String.sub line 0 200 ^ "…" else line in
            (* Keep tabs so the caret lines up with the source as a terminal shows it. *)
            let pad =
              String.init
                (max 0 (min (loc.col - 1) (String.length line)))
                (fun i -> if i < String.length line && line.[i] = '\t' then '\t' else ' ')
            in
            Printf.sprintf "%5d | %s\n      | %s^\n" loc.line line pad)

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
