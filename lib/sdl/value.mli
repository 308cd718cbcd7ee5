(** Values of the scene language and POV-Ray's arithmetic on them (POVRAY-3.7 §11.2). *)

(** An object as declared: its texture and interior are filled in only when it enters the scene. *)
type obj = {
  shape : Scene.shape;
  texture : Scene.texture option;
  interior : Scene.interior option;
  no_shadow : bool;
  oloc : Loc.t;
}

type t =
  | Float of float
  | Vector of float array  (** 2 to 5 terms *)
  | Colour of float array  (** always 5 terms: r g b f t *)
  | String of string
  | Pigment of Scene.pigment
  | Finish of Scene.finish
  | Texture of Scene.texture
  | Interior of Scene.interior
  | Object of obj

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
