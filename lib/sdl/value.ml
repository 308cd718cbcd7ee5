(* Values of the scene language and POV-Ray's arithmetic on them (docs/povray-rules.md §11.2). *)

type obj = {
  shape : shape;
  texture : Scene.texture option;
  interior_texture : Scene.texture option;
  uv_mapped : bool;  (** [uv_mapping]: its textures are evaluated at the hit's (u, v, 0), and transforms leave them *)
  difference : bool;  (** a CSG written as [difference] *)
  cutaway : bool;  (** [cutaway_textures] (an intersection or difference): members without a texture show those of the members around them *)
  interior : Scene.interior option;
  no_shadow : bool;
  oloc : Loc.t;
  no_image : bool;
  no_reflection : bool;
  double_illuminate : bool;
  looks_like : bool;  (** a light's looks_like object (§19.2) *)
  inverted : bool;  (** [inverse] was applied: a primitive's Inside is negated, a CSG was morphed (§16.3) *)
  linked : bool;  (** [clipped_by { bounded_by }] or [bounded_by { clipped_by }]: its clip and bounding objects are one list *)
}

(** A primitive, or a CSG: a union with [split] on is dissolved into its members when it enters
    the scene (docs/povray-rules.md §16.4); any other CSG is kept whole. *)
and shape = Prim of Scene.shape | Csg of { kind : Scene.csg_kind; members : member list; split : bool; box : float array option }

and member = Member_obj of obj | Member_light of Scene.light

(** The camera as written; the rules of §1.3 are applied when the scene is finished. *)
type camera_spec = {
  c_location : Vec.t option;
  c_direction : Vec.t option;
  c_up : Vec.t option;
  c_right : Vec.t option;
  c_sky : Vec.t option;
  c_look_at : (Vec.t * Loc.t) option;
  c_angle : (float * Loc.t) option;
  c_trans : Transform.t option;
  c_ortho : bool;  (** the orthographic keyword was written (§18.4) *)
}

(** A macro: its parameters and where its body starts in the text that defines it. *)
type macro = { mname : string; params : string list; source : Lexer.t; body : Lexer.mark; mloc : Loc.t }

(** A random stream made by [seed(n)] (§11.2). *)
type stream = { mutable state : int }

(** A [material]: what an object takes from it (parstxtr.cpp's MATERIAL): textures layered over
    the object's, and an interior. *)
type material = { mtexture : Scene.texture option; minterior_texture : Scene.texture option; minterior : Scene.interior option }

(** A file opened by [#fopen]: its path and what it is open for. Reading, the whole text is read
    at [#fopen] and tokens are taken from it; the file is [Closed] by [#fclose], at the end of the
    data, and when the scene ends. *)
type user_file = { path : string; mutable io : io }

and io = Reading of Lexer.t | Writing of out_channel | Closed

type t =
  | Float of float
  | Vector of float array
  | Colour of float array
  | String of string
  | Pigment of Scene.pigment
  | Normal of Scene.normal
  | Sky of Scene.sky
  | Finish of Scene.finish
  | Texture of Scene.texture
  | Interior of Scene.interior
  | Object of obj
  | Light of Scene.light
  | Camera of camera_spec
  | Array of array_v
  | Macro of macro
  | Transform of Transform.t
  | Unsupported of { what : string; at : Loc.t }
      (** a declaration that uses a feature povml cannot render yet: an error only where it is used *)
  | File of user_file  (** the identifier [#fopen] declares *)
  | Colour_map of Scene.map_entry array  (** a declared [color_map] (docs/povray-rules.md §17.3) *)
  | Pigment_map of Scene.pigment_entry array  (** a declared [pigment_map] (§17.3) *)
  | Texture_map of Scene.texture_entry array  (** a declared [texture_map] *)
  | Material of material  (** a declared [material] *)
  | Spline of Spline.t  (** a declared [spline] (§11.5) *)
  | Function of Fn.t  (** a declared [function] (a float function, or a vector function of a pigment, transform or spline) *)

(** An array: its dimensions and its elements in row-major order, [None] until assigned. *)
and array_v = { dims : int array; cells : t option array }

let kind_name = function
  | Float _ -> "a float"
  | Vector a -> Printf.sprintf "a %d-term vector" (Array.length a)
  | Colour _ -> "a colour"
  | String _ -> "a string"
  | Pigment _ -> "a pigment"
  | Normal _ -> "a normal"
  | Sky _ -> "a sky_sphere"
  | Finish _ -> "a finish"
  | Texture _ -> "a texture"
  | Interior _ -> "an interior"
  | Object _ -> "an object"
  | Light _ -> "a light_source"
  | Camera _ -> "a camera"
  | Array a -> Printf.sprintf "an array of %s" (String.concat "×" (List.map string_of_int (Array.to_list a.dims)))
  | Macro _ -> "a macro"
  | Transform _ -> "a transform"
  | Unsupported u -> Printf.sprintf "a value that uses %s" u.what
  | File f -> Printf.sprintf "the file \"%s\" opened by #fopen" f.path
  | Colour_map _ -> "a color_map"
  | Pigment_map _ -> "a pigment_map"
  | Texture_map _ -> "a texture_map"
  | Material _ -> "a material"
  | Spline _ -> "a spline"
  | Function f -> if f.Fn.size = 0 then "a function" else "a vector function"

let terms = function
  | Float _ -> 1
  | Vector a | Colour a -> Array.length a
  | String _ | Pigment _ | Normal _ | Sky _ | Finish _ | Texture _ | Interior _ | Object _ | Light _ | Camera _ | Array _ | Macro _ | Transform _ | Unsupported _ | File _ | Colour_map _ | Pigment_map _ | Texture_map _ | Material _ | Spline _ | Function _ -> 0

(* docs/povray-rules.md §11.2: a float is replicated into every term, a shorter vector is padded with zeros. *)
let promote v n =
  match v with
  | Float f -> Array.make n f
  | Vector a | Colour a -> Array.init n (fun i -> if i < Array.length a then a.(i) else 0.)
  | String _ | Pigment _ | Normal _ | Sky _ | Finish _ | Texture _ | Interior _ | Object _ | Light _ | Camera _ | Array _ | Macro _ | Transform _ | Unsupported _ | File _ | Colour_map _ | Pigment_map _ | Texture_map _ | Material _ | Spline _ | Function _ -> invalid_arg "Value.promote"

let numeric v = terms v > 0

let arith op a b =
  match (a, b) with
  | Float x, Float y -> Some (Float (op x y))
  | _ when numeric a && numeric b ->
      let is_colour = (match a with Colour _ -> true | _ -> false) || match b with Colour _ -> true | _ -> false in
      let n = if is_colour then 5 else max (terms a) (terms b) in
      let pa = promote a n and pb = promote b n in
      let r = Array.init n (fun i -> op pa.(i) pb.(i)) in
      Some (if is_colour then Colour r else Vector r)
  | _ -> None

let map f = function
  | Float x -> Some (Float (f x))
  | Vector a -> Some (Vector (Array.map f a))
  | Colour a -> Some (Colour (Array.map f a))
  | String _ | Pigment _ | Normal _ | Sky _ | Finish _ | Texture _ | Interior _ | Object _ | Light _ | Camera _ | Array _ | Macro _ | Transform _ | Unsupported _ | File _ | Colour_map _ | Pigment_map _ | Texture_map _ | Material _ | Spline _ | Function _ -> None
