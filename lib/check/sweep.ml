(* The settings povml report sweeps, and the results measured for each. *)

type setting = { antialias : float option; method_ : int; depth : int; trace_level : int option }

let dedup l = List.rev (List.fold_left (fun acc x -> if List.mem x acc then acc else x :: acc) [] l)

let settings ~aa ~trace ~thresholds ~methods ~depths ~trace_levels =
  let off = { antialias = None; method_ = 1; depth = 3; trace_level = None } in
  let aa_part =
    if not aa then []
    else
      off
      :: List.concat_map
           (fun m ->
             List.concat_map (fun d -> List.map (fun t -> { antialias = Some t; method_ = m; depth = d; trace_level = None }) thresholds) depths)
           methods
  in
  let trace_part = if not trace then [] else List.map (fun n -> { off with trace_level = Some n }) trace_levels in
  dedup (aa_part @ trace_part)

let threshold t =
  let s = Printf.sprintf "%g" t in
  if String.contains s '.' || String.contains s 'e' then s else s ^ ".0"

let switches s =
  match s.antialias with
  | None -> [ "-A" ]
  | Some t -> [ "+A" ^ threshold t; Printf.sprintf "+AM%d" s.method_; Printf.sprintf "+R%d" s.depth ]

let label s =
  String.concat " " (switches s) ^ match s.trace_level with None -> "" | Some n -> Printf.sprintf " max_trace_level %d" n

let with_trace_level text n =
  Printf.sprintf "%s\n// povml report: the swept max_trace_level\nglobal_settings { max_trace_level %d }\n" text n

type measured =
  | Rendered of { times : float list; median : float; cmp : Compare.t }
  | Not_supported of string
  | Failed of string

type row = { setting : setting; povml : measured; povray : measured }

type scene = {
  path : string;
  stem : string;
  width : int;
  height : int;
  switches : string list;
  truth : string list;
  truth_seconds : float;
  runs : int;
  rows : row list;
}

let get row = function `Povml -> row.povml | `Povray -> row.povray

let front scene r =
  let rendered = List.filter (fun row -> match get row r with Rendered _ -> true | _ -> false) scene.rows in
  Pareto.front (fun row -> match get row r with Rendered m -> (m.median, m.cmp.rmse) | _ -> (infinity, infinity)) rendered
