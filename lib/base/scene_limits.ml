(* The limits on what a scene may ask for, and their defaults. *)

type t = {
  include_depth : int;
  macro_depth : int;
  macro_calls : int;
  iterations : int;
  objects : int;
  nesting : int;
  memory_mb : int;
  pixels : int;
  pattern_steps : int;
  function_steps : int;
  string_mb : int;
}

(* Half the address space the process may use (ulimit -v), read from /proc/self/limits on Linux;
   None when unlimited or unknown. *)
let address_space_mb () =
  match open_in "/proc/self/limits" with
  | exception Sys_error _ -> None
  | ic ->
      let rec find () =
        match input_line ic with
        | exception End_of_file -> None
        | line when String.length line > 17 && String.sub line 0 17 = "Max address space" -> (
            match List.filter (( <> ) "") (String.split_on_char ' ' (String.sub line 17 (String.length line - 17))) with
            | soft :: _ -> Option.map (fun b -> b / (1 lsl 20)) (int_of_string_opt soft)
            | [] -> None)
        | _ -> find ()
      in
      let r = find () in
      close_in_noerr ic;
      r

let default_memory_mb = match address_space_mb () with Some mb -> min 4096 (mb / 2) | None -> 4096

let default =
  {
    include_depth = 64;
    macro_depth = 10_000;
    macro_calls = 3_000_000;
    iterations = 10_000_000;
    objects = 10_000_000;
    nesting = 10_000;
    memory_mb = default_memory_mb;
    pixels = 8192 * 8192;
    pattern_steps = 100_000;
    function_steps = 1_000_000_000;
    string_mb = 4096;
  }
