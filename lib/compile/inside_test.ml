(* An object's Inside test for an object pattern: the object's geometry compiled as Compile
   compiles a scene object's, keeping only what the Inside tests read (shapes, CSG kinds,
   inversion); it has no surface, interior or place among a scene's objects. *)

open Compiled

(* the compiled shape of [s], its members compiled the same way (Compile.scene's [build]) *)
let rec shape (s : Scene.shape) : Compiled.shape option =
  match s with
  | Csg { kind; members } ->
      let members =
        List.filter_map
          (fun (m : Scene.member) ->
            (* an Inside test reads a member's shape and inversion only: no id, box or magnitude *)
            Option.map (fun sh -> { id = 0; inverted = m.inverted; shape = sh; pbox = [||]; mag = 0. }) (shape m.mobj.shape))
          members
      in
      Some (Csg { kind; members = Array.of_list members; cbox = [||] })
  | primitive ->
      (* an Inside test never searches an isosurface, so never asks a worker for its state *)
      Shape.compile ~iso_slot:0 primitive

let of_object (o : Scene.obj) =
  match shape o.shape with
  | None -> fun _ -> false
  | Some compiled ->
      (* the traversal room of mesh Inside tests, the pattern's own (a pattern is given no
         worker's room): written by each test before it is read, and each worker is a process *)
      let stack = Array.make 512 0. in
      fun p -> Shape.inside stack compiled p
