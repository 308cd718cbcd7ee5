(* POV-Ray switches as povml check and povml report hand them to both renderers. *)

(* The names POV-Ray's switches start with; the longest that matches is the switch's name. *)
let names = [ "AM"; "AG"; "WT"; "SR"; "ER"; "SC"; "EC"; "BS"; "A"; "D"; "F"; "H"; "I"; "J"; "K"; "L"; "O"; "R"; "V"; "W" ]

let key s =
  let n = String.length s in
  if n < 2 || (s.[0] <> '+' && s.[0] <> '-') || s.[1] = '-' then None
  else
    let up = String.uppercase_ascii (String.sub s 1 (n - 1)) in
    let starts p = String.length up >= String.length p && String.sub up 0 (String.length p) = p in
    match List.find_opt starts names with Some k -> Some k | None -> Some up

let value s =
  match key s with
  | None -> s
  | Some k ->
      let from = 1 + min (String.length k) (String.length s - 1) in
      String.sub s from (String.length s - from)

let mem k switches = List.exists (fun s -> key s = Some k) switches

let system_include =
  let d = "/usr/share/povray-3.7/include" in
  if Sys.file_exists d then Some d else None

let defaults switches =
  List.filter_map (fun (k, v) -> if mem k switches then None else Some v) [ ("W", "+W160"); ("H", "+H120"); ("WT", "+WT2") ]

let shown switches = switches @ defaults switches

let absolute ~cwd p = if Filename.is_relative p then Filename.concat cwd p else p

let for_renderers ~cwd ~scene switches =
  let scene_dir = Filename.dirname (absolute ~cwd scene) in
  let user =
    List.map (fun s -> if key s = Some "L" && value s <> "" then "+L" ^ absolute ~cwd (value s) else s) switches
  in
  defaults switches
  @ [ "+L" ^ scene_dir; "+L" ^ cwd ]
  @ user
  @ (match system_include with Some d -> [ "+L" ^ d ] | None -> [])
  @ [ "-D"; "-V"; "+FN" ]
