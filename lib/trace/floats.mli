(** The minimum and maximum of floats as the standard library's [Float.min] and [Float.max] give
    them, for every pair of arguments (−0 below +0, a NaN argument returned as they return it), in
    line: without the C call for the sign bit that theirs make on every comparison. *)

val max : float -> float -> float
(** [max x y] is [Float.max x y]. *)

val min : float -> float -> float
(** [min x y] is [Float.min x y]. *)

val max3 : Rgb.t -> float
(** [max3 c] is [Rgb.max3 c], the largest channel. *)
