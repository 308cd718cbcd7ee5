(* POV-Ray's precision rules in one place: single-precision rounding and the shared tolerances. *)

(* One single-precision cell: storing a float rounds it to single precision (the C cast POV-Ray
   makes), reading it back widens it exactly. The compiler does both in line, without the two C
   calls of Int32.bits_of_float and Int32.float_of_bits; a worker is a process, so the cell is never
   shared. *)
let cell = Bigarray.Array1.create Bigarray.float32 Bigarray.c_layout 1

let[@inline] f32 x =
  Bigarray.Array1.unsafe_set cell 0 x;
  Bigarray.Array1.unsafe_get cell 0
let epsilon = 1e-10
let min_isect_depth = 1e-4
let shadow_tolerance = 1e-3
