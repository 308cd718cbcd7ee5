(** Float images: the linear colours the tracer produced, before encoding. *)

type t = { width : int; height : int; data : Float.Array.t  (** r g b per pixel, row-major from the top *) }

val create : int -> int -> t
(** [create w h] is a black image. *)

val get : t -> int -> int -> float * float * float
(** [get img x y] is the colour of pixel (x, y). *)

val set : t -> int -> int -> float -> float -> float -> unit
(** [set img x y r g b] stores a colour. *)
