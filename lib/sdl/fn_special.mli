(** The vector functions made of other values (function.cpp's pigment, transform and spline
    functions, fnintern.cpp's f_pigment, f_transform and f_spline), and pattern functions. *)

val spline : Spline.t -> Loc.t -> Fn.t
(** [spline s loc] is the vector function of one parameter, the time, whose terms are [s]'s
    value then. *)

val spline_value : Spline.t -> float -> Value.t
(** [spline_value s t] is [s]'s value at [t] as the scene language sees it: a vector of the
    spline's terms (a colour for five). *)
