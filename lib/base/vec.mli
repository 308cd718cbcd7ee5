(** Three-component double vectors, stored unboxed (an all-float record). *)

type t = { x : float; y : float; z : float }

val make : float -> float -> float -> t
(** [make x y z] is the vector <x,y,z>. *)

val zero : t
(** [zero] is <0,0,0>. *)

val add : t -> t -> t
(** [add a b] is a + b. *)

val sub : t -> t -> t
(** [sub a b] is a − b. *)

val neg : t -> t
(** [neg a] is −a. *)

val scale : float -> t -> t
(** [scale s a] is s·a. *)

val mul : t -> t -> t
(** [mul a b] is the component-wise product. *)

val dot : t -> t -> float
(** [dot a b] is a·b. *)

val cross : t -> t -> t
(** [cross a b] is a×b. *)

val length : t -> float
(** [length a] is |a|. *)

val length2 : t -> float
(** [length2 a] is |a|². *)

val normalize : t -> t
(** [normalize a] is a/|a|; the zero vector is returned unchanged. *)

val madd : t -> float -> t -> t
(** [madd a s b] is a + s·b. *)

val to_string : t -> string
(** [to_string a] is "<x, y, z>" with POV-Ray-like float formatting. *)
