(** Float images: the linear colours the tracer produced, before encoding.

    Each channel is kept in single precision, as POV-Ray keeps its image and as [Encode] reads
    it (its first step rounds a channel to single precision): the image is the same, in half the
    memory (an 8192×8192 image is 805 MB). *)

type t = {
  width : int;
  height : int;
  data : (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t;
      (** r g b per pixel, row-major from the top *)
}

val create : int -> int -> t
(** [create w h] is a black image. *)

val get : t -> int -> int -> float * float * float
(** [get img x y] is the colour of pixel (x, y). *)

val set : t -> int -> int -> float -> float -> float -> unit
(** [set img x y r g b] stores a colour, each channel rounded to single precision. *)

val channel : t -> int -> float
(** [channel img i] is the [i]th value of [data]. *)

val channels : t -> int
(** [channels img] is the number of values in [data]: 3 × width × height. *)
