(* The fuzz target. The only acceptable outcomes of reading a scene are a scene (with warnings) and
   [Error.Scene_error]; Not_found, Invalid_argument, Stack_overflow, Out_of_memory … are bugs. *)

open Povml

(* The macro depth and include depth stay at their defaults: a default that overflows the stack is
   a bug the fuzzer should find. The others are lower so that a scene that is merely big ends in
   well under AFL++'s time limit for one input. *)
let limits =
  {
    Scene_limits.default with
    iterations = 10_000;
    macro_calls = 10_000;
    objects = 10_000;
    nesting = 2_000;
    memory_mb = 512;
  }

type outcome = Scene of int | Refused of Error.t | Bug of string

let size = 8

let options =
  let o = Interp.default_options ~width:size ~height:size in
  (* #debug text would only flood the fuzzer's output *)
  { o with debug = ignore; limits }

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
  | exception Error.Scene_error e -> Refused e
  | exception e -> Bug (describe e)
  | scene, warnings -> (
      match if render then render_scene scene with
      | () -> Scene (List.length warnings)
      | exception Error.Scene_error e -> Refused e
      | exception e -> Bug (describe e))
