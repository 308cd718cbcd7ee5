(* POV-Ray's precision rules in one place: single-precision rounding and the shared tolerances. *)

let[@inline] f32 x = Int32.float_of_bits (Int32.bits_of_float x)
let epsilon = 1e-10
let min_isect_depth = 1e-4
let shadow_tolerance = 1e-3
