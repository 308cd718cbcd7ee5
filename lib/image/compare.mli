(** Comparing two encoded images of the same size. *)

type t = {
  pixels : int;  (** pixels compared *)
  differing : int;  (** pixels with any channel different *)
  peak : int;  (** largest channel difference, in 1/255 units *)
  rmse : float;  (** root-mean-square channel difference, in 1/255 units *)
}

val images : Encode.t -> Encode.t -> (t, string) result
(** [images a b] compares [a] and [b]; an error when the sizes differ. *)

val identical_share : t -> float
(** [identical_share c] is the share of identical pixels, 0 … 1. *)

val psnr : t -> float
(** [psnr c] is the peak signal-to-noise ratio in dB (infinity when identical). *)

val differing_share : t -> float
(** [differing_share c] is the share of pixels with any channel different, 0 … 1 (differing / pixels, exactly). *)
