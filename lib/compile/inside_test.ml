(* An object's Inside test for an object pattern: the object compiled as Compile compiles a scene
   object, keeping only what the Inside tests read (shapes, CSG kinds, inversion); surfaces,
   interiors and ids are never read by [Shape.inside] and get neutral values. *)

open Compiled

(* what the Inside tests never read, in the fields a compiled object must have: the default
   texture's surface *)
let no_surface = Compile.surface ~legacy:false ~noise:2 ~ambient_light:Rgb.black Defaults.layer

let clear_interior : Compiled.interior = { ior = 1.; fade_distance = 0.; fade_power = 0.; fade_colour = Rgb.black; caustics = 0. }

let member ~inverted shape =
  {
    id = 0;
    iid = 0;
    top = 0;
    cache = 0;
    inverted;
    shape;
    tex = Plain no_surface;
    inner_tex = None;
    face_texs = [||];
    clear = false;
    uv_mapped = false;
    difference = false;
    interior = clear_interior;
    old_refract = 1.;
    opaque = true;
    mag = 0.;
    pbox = [||];
    double_illuminate = false;
  }

(* the compiled shape of [s], its members compiled the same way (Compile.scene's [build]) *)
let rec shape (s : Scene.shape) : Compiled.shape option =
  match s with
  | Csg { kind; members } ->
      let members =
        List.filter_map (fun (m : Scene.member) -> Option.map (member ~inverted:m.inverted) (shape m.mobj.shape)) members
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
