(** Five-channel colours of the scene language: red, green, blue, filter, transmit. *)

type t = { red : float; green : float; blue : float; filter : float; transmit : float }

val black : t
(** [black] is rgbft <0,0,0,0,0>. *)

val of_array : float array -> t
(** [of_array a] reads up to five terms; missing ones are 0. *)

val rgb : t -> Rgb.t
(** [rgb c] drops filter and transmit. *)

val transmitted : t -> Rgb.t
(** [transmitted c] is rgb·filter + transmit per channel, the light passed through (§3.5). *)
