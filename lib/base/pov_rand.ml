(* POV_rand's linear congruential stream; the state lives in one mutable field of the worker's. *)

type t = { mutable state : int }

let create () = { state = 0 }

let next s =
  let next = ((s.state * 1812433253) + 12345) land 0xFFFFFFFF in
  s.state <- next;
  float_of_int next /. 4294967295.
