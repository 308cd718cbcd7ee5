(** From linear working colours to 8-bit file values (docs/povray-rules.md §8.1). *)

type t = { width : int; height : int; pixels : Bytes.t  (** r g b bytes per pixel, row-major *) }

(** How the working colour space maps to the file (the scene's [gamma], §8.1). *)
type gamma =
  | Gamma_off  (** legacy scene without assumed_gamma: output = clip(linear) *)
  | Working of float  (** working gamma G (1.0 neutral); the file is sRGB-encoded *)

val channel : gamma -> float -> int
(** [channel gamma x] is the 8-bit value for the working-space value [x]: decoded by the working gamma,
    sRGB-encoded in single precision, clipped and rounded; identity before clipping when gamma is off. *)

val image : gamma -> Image.t -> t
(** [image gamma img] encodes every pixel. *)
