(** A difference heat map of two images of the same size. *)

val colour : peak:int -> int -> int * int * int
(** [colour ~peak d] is the colour of a pixel whose largest channel difference is [d] (1 … [peak]):
    a ramp from blue (the smallest difference) through magenta and red to yellow ([d = peak]). *)

val image : Encode.t -> Encode.t -> (Encode.t, string) result
(** [image a b] is the heat map of [a] against [b]: an equal pixel shows [a]'s luminance dimmed to
    0 … 63 (dark grey), a differing one [colour ~peak d] with [peak] the largest difference in the
    image; an error when the sizes differ. *)
