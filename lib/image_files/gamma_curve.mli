(** POV-Ray 3.7's transfer functions between encoded file values and linear values
    (base/image/colourspace.cpp), in single precision as POV-Ray computes them, with the same
    simplifications its factories make (a curve within 1% of neutral is neutral, a transcoding
    between matching curves is neutral, two power laws combine into one). *)

type t =
  | Neutral  (** the identity (POV-Ray's null curve too) *)
  | Srgb  (** the sRGB curve *)
  | Power of float  (** x^(1/g) to decode; [g] the encoding gamma, single precision *)
  | Scaled of t * float  (** a curve whose encoded values are scaled by the factor (PPM/PGM depths) *)
  | Transcoding of { working : t; encoding : t }
      (** decodes by the encoding curve, then encodes by the working curve *)

val by_decoding_gamma : float -> t
(** [by_decoding_gamma g] is PowerLawGammaCurve::GetByDecodingGamma: the power law of encoding
    gamma [1/g] (single precision), or [Neutral] within 1% of 1. *)

val by_encoding_gamma : float -> t
(** [by_encoding_gamma g] is PowerLawGammaCurve::GetByEncodingGamma. *)

val scaled_by_decoding : float -> t -> t
(** [scaled_by_decoding f c] is ScaledGammaCurve::GetByDecoding: [c] with encoded values divided
    by [1/f], or [c] itself when [f] is within 1e-6 of 1. *)

val transcoding : working:t -> encoding:t -> t
(** [transcoding ~working ~encoding] is TranscodingGammaCurve::Get: the curve from a file
    encoded by [encoding] to the working space of [working]. *)

val is_neutral : t -> bool
(** [is_neutral c] holds for the identity. *)

val decode : t -> float -> float
(** [decode c x] is the linear value of the encoded value [x], in single precision. *)

val encode : t -> float -> float
(** [encode c x] is the encoded value of the linear value [x], in single precision. *)

val lookup_table : t -> int -> float array
(** [lookup_table c max] is GammaCurve::GetLookupTable: [decode c (i / max)] for i = 0 … [max]. *)
