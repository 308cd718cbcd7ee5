(* C's arithmetic as POV-Ray's pattern code uses it, and the constants it writes out. *)

(* C's (int) cast of a double: truncation; NaN and values out of range give INT_MIN, as the x86
   conversion instruction does *)
let[@inline] c_int (x : float) = if x >= -2147483648. && x < 2147483648. then truncate x else -2147483648

(* std::max and std::min as POV-Ray calls them: the first argument unless the comparison says
   otherwise, which decides NaNs and signed zeros *)
let[@inline] fmax (a : float) b = if a < b then b else a
let[@inline] fmin (a : float) b = if b < a then b else a
let[@inline] max3 a b c = fmax a (fmax b c)

let sqrt3_2 = 0.86602540378443864676372317075294
let sqrt3 = 1.7320508075688772935274463415059
let sqrt2 = 1.4142135623730950488016887242097
let sqrt2_2 = 0.70710678118654752440084436210485

let int_cast x = if Float.is_nan x || Float.abs x >= 2147483648. then -2147483648. else Float.trunc x +. 0.
