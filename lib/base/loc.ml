(* Source locations. *)

type t = { file : string; line : int; col : int }

let none = { file = ""; line = 0; col = 0 }
let to_string l = Printf.sprintf "%s:%d:%d" l.file l.line l.col
