(* The fuzz target. The only acceptable outcomes of reading a scene are a scene (with warnings) and
   [Error.Scene_error]; Not_found, Invalid_argument, Stack_overflow, Out_of_memory … are bugs. *)

(* Lower than the defaults, so that a scene that is merely big ends in well under AFL++'s time
   limit for one input. The macro depth especially: every identifier is looked up through one
   table per macro call in progress, so a recursion 10,000 deep (the default) takes one to three
   seconds to reach the limit. The include depth stays at its default. *)
let limits =
  {
    Scene_limits.default with
    iterations = 10_000;
    macro_calls = 10_000;
    macro_depth = 1_000;
    objects = 10_000;
    nesting = 2_000;
    memory_mb = 128;
    function_steps = 10_000_000;
    string_mb = 64;
  }

type outcome = Scene of int | Refused of Error.t | Bug of string

let size = 8

let options =
  let o = Interp.default_options ~width:size ~height:size in
  (* #debug text would only flood the fuzzer's output *)
  (* Access.default: the scene reads under the working directory and POV-Ray's include files, and
     writes nowhere, so no input can leave a file behind *)
  { o with debug = ignore; limits; access = Access.default }

(* The interpreter turns Stack_overflow and Out_of_memory into located limit errors as a last line
   of defence; with the limits above, reaching either means a limit that should have come first
   did not, so they count as bugs. The messages are the only way to tell them apart. *)
let last_resort (e : Error.t) =
  let starts p = String.length e.msg >= String.length p && String.sub e.msg 0 (String.length p) = p in
  e.kind = Limit && (starts "the scene nests too deeply for the stack" || starts "the scene needs more memory than the system")

let render_scene (scene : Scene.t) =
  let compiled = Compile.scene scene in
  let img, _ = Render.render (Render.defaults size size) compiled scene.gamma in
  ignore (Encode.image scene.gamma img)

let run ?(render = true) ~file text =
  let describe e =
    (* the innermost calls are enough, and a stack overflow has a hundred thousand *)
    let bt = String.split_on_char '\n' (Printexc.get_backtrace ()) |> List.filteri (fun i _ -> i < 16) in
    String.concat "\n" (Printexc.to_string e :: bt)
  in
  match Interp.load_string options ~file text with
  | exception Error.Scene_error e when last_resort e -> Bug ("a limit came too late: " ^ e.msg)
  | exception Error.Scene_error e -> Refused e
  | exception e -> Bug (describe e)
  | scene, warnings -> (
      match if render then render_scene scene with
      | () -> Scene (List.length warnings)
      | exception Error.Scene_error e -> Refused e
      | exception e -> Bug (describe e))
