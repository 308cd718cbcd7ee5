(** Values of the scene language and POV-Ray's arithmetic on them (docs/povray-rules.md §11.2). *)

(** An object as declared: its texture and interior are filled in only when it enters the scene. *)
type obj = {
  shape : shape;
  texture : Scene.texture option;
  interior_texture : Scene.texture option;  (** [interior_texture]: seen from inside the surface *)
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
    the scene (docs/povray-rules.md §16.4); any other CSG is kept whole. [box] is {!Scene.shape}'s: POV-Ray's
    box of a union or merge as its history made it. *)
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
  | Vector of float array  (** 2 to 5 terms *)
  | Colour of float array  (** always 5 terms: r g b f t *)
  | String of string
  | Pigment of Scene.pigment
  | Normal of Scene.normal  (** a declared [normal] *)
  | Sky of Scene.sky  (** a declared [sky_sphere] *)
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

val kind_name : t -> string
(** [kind_name v] names the type for messages, e.g. "a float" or "a pigment". *)

val terms : t -> int
(** [terms v] is 1 for a float, the number of terms of a vector or colour, 0 otherwise. *)

val promote : t -> int -> float array
(** [promote v n] is [v] widened to [n] terms: a float is replicated, a vector padded with zeros. *)

val arith : (float -> float -> float) -> t -> t -> t option
(** [arith op a b] applies [op] term by term after promoting the shorter operand; a colour operand
    makes a colour. [None] when an operand is not numeric. *)

val map : (float -> float) -> t -> t option
(** [map f v] applies [f] to every term of a numeric value. *)
