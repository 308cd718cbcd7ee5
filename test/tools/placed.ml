(* Renders a scene whose object modifiers (translate, rotate, scale, matrix) the interpreter cannot
   read yet: each modifier written alone on a line at the top level of an object is taken out of
   the text and applied with Place.shape after interpretation, in the order written. The same file
   renders unchanged in POV-Ray, so the two images can be compared pixel for pixel.
   Usage: placed.exe SCENE.pov OUT.png WIDTH HEIGHT *)

open Povml

let object_words = [ "sphere"; "plane"; "triangle"; "smooth_triangle"; "mesh"; "mesh2" ]

let floats s =
  let s = String.map (fun c -> if c = '<' || c = '>' then ' ' else c) s in
  List.map (fun x -> float_of_string (String.trim x)) (String.split_on_char ',' s)

let vector s =
  match floats s with
  | [ f ] -> Vec.make f f f
  | [ x; y; z ] -> Vec.make x y z
  | _ -> failwith ("not a vector: " ^ s)

let op_of word rest : Place.op =
  match word with
  | "translate" -> Translate (vector rest)
  | "rotate" -> Rotate (vector rest)
  | "scale" ->
      let v = vector rest in
      let nz x = if x = 0. then 1. else x in
      Scale (Vec.make (nz v.x) (nz v.y) (nz v.z))
  | "matrix" -> (
      match Transform.matrix (Array.of_list (floats rest)) with
      | Ok (t, warnings) -> List.iter prerr_endline warnings; Transform t
      | Error e -> failwith e)
  | _ -> assert false

let () =
  let path = Sys.argv.(1) and out = Sys.argv.(2) in
  let width = int_of_string Sys.argv.(3) and height = int_of_string Sys.argv.(4) in
  let text = let ic = open_in_bin path in let s = really_input_string ic (in_channel_length ic) in close_in ic; s in
  let depth = ref 0 and index = ref (-1) and ops = ref [] and kept = Buffer.create 4096 in
  List.iter
    (fun line ->
      let t = String.trim line in
      let word, rest =
        match String.index_opt t ' ' with Some i -> (String.sub t 0 i, String.sub t i (String.length t - i)) | None -> (t, "")
      in
      let word = match String.index_opt word '{' with Some i -> String.sub word 0 i | None -> word in
      if !depth = 0 && List.mem word object_words then incr index;
      if !depth = 1 && List.mem word [ "translate"; "rotate"; "scale"; "matrix" ] then ops := (!index, op_of word rest) :: !ops
      else begin
        Buffer.add_string kept line;
        Buffer.add_char kept '\n'
      end;
      String.iter (fun c -> if c = '{' then incr depth else if c = '}' then decr depth) line)
    (String.split_on_char '\n' text);
  let ops = List.rev !ops in
  let scene, _ = Interp.load_string { Interp.width; height } ~file:path (Buffer.contents kept) in
  let objects =
    List.mapi
      (fun i (o : Scene.obj) ->
        let shape = List.fold_left (fun s (j, op) -> if i = j then Place.shape s op else s) o.shape ops in
        { o with shape })
      scene.objects
  in
  let scene = { scene with objects } in
  let opts =
    {
      Render.width;
      height;
      antialias = None;
      aa_depth = 3;
      jitter = 0.;
      aa_gamma = 2.5;
      area = Render.full_area width height;
      block_size = 32;
      workers = 1;
      progress = false;
    }
  in
  let img, _ = Render.render opts (Compile.scene scene) scene.gamma in
  match Output.write Output.Png out (Encode.image scene.gamma img) with Ok () -> () | Error e -> failwith e
