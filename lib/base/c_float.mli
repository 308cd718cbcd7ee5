(** C's arithmetic as POV-Ray's pattern code uses it (pattern.cpp), and the constants it writes
    out, so that the patterns' values are the doubles POV-Ray computes. *)

val c_int : float -> int
(** [c_int x] is C's [(int)] cast: truncation toward zero; NaN and values out of the 32-bit range
    give INT_MIN (−2³¹), as the x86 conversion does. *)

val int_cast : float -> float
(** [int_cast x] is C's [(double)(int)x] as POV-Ray's parser and function VM write [int()]:
    truncation, −2³¹ for NaN and what does not fit, and a zero without a sign ([int_cast (-0.5)] is
    [0.], not [-0.]). *)

val fmax : float -> float -> float
(** [fmax a b] is [std::max(a, b)]: [b] when [a < b], else [a] (which decides NaNs and zeros). *)

val fmin : float -> float -> float
(** [fmin a b] is [std::min(a, b)]: [b] when [b < a], else [a]. *)

val max3 : float -> float -> float -> float
(** [max3 a b c] is [fmax a (fmax b c)]. *)

val sqrt3_2 : float
(** [sqrt3_2] is √3/2 as pattern.cpp writes it. *)

val sqrt3 : float
(** [sqrt3] is √3 as pattern.cpp writes it. *)

val sqrt2 : float
(** [sqrt2] is √2 as pattern.cpp writes it. *)

val sqrt2_2 : float
(** [sqrt2_2] is √2/2 as pattern.cpp writes it. *)
