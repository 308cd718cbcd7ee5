(* The string functions of the scene language that need more than a line (docs/povray-rules.md §11.2). *)

(* str(V, L, P): printf's %[L].[P]f: P digits after the point (6 when P < 0), at least |L|
   characters, padded with zeros when L < 0 and with spaces when L > 0. *)
let str v l p =
  let body = if p >= 0 then Printf.sprintf "%.*f" p v else Printf.sprintf "%f" v in
  let w = abs l in
  let n = String.length body in
  if n >= w then body
  else if l < 0 then
    (* zeros go after the sign, as printf's 0 flag puts them *)
    if body.[0] = '-' then "-" ^ String.make (w - n) '0' ^ String.sub body 1 (n - 1) else String.make (w - n) '0' ^ body
  else String.make (w - n) ' ' ^ body

let vstr terms sep l p = String.concat sep (Array.to_list (Array.map (fun v -> str v l p) terms))

(* val(S): the number at the start of S, as C's atof reads it (0 when there is none). *)
let value s =
  let s = String.trim s in
  let n = String.length s in
  let best = ref 0. in
  for i = 1 to n do
    match float_of_string_opt (String.sub s 0 i) with Some f when i = 1 || s.[i - 1] <> '_' -> best := f | _ -> ()
  done;
  !best

(* strcmp(A, B): the difference of the first differing bytes, as POV-Ray prints it ("A" vs "a" is −32) *)
let compare a b =
  let la = String.length a and lb = String.length b in
  let rec go i =
    let ca = if i < la then Char.code a.[i] else 0 and cb = if i < lb then Char.code b.[i] else 0 in
    if ca <> cb || i >= la then ca - cb else go (i + 1)
  in
  go 0
