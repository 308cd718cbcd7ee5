(** From linear working colours to 8-bit file values (docs/povray-rules.md §8.1). *)

type t = { width : int; height : int; pixels : Bytes.t  (** r g b bytes per pixel, row-major *) }

val channel : Scene.gamma -> float -> int
(** [channel gamma x] is the 8-bit value for the working-space value [x]: decoded by the working gamma,
    sRGB-encoded in single precision, clipped and rounded; identity before clipping when gamma is off. *)

val image : Scene.gamma -> Image.t -> t
(** [image gamma img] encodes every pixel. *)
