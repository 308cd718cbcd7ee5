(* The step budget of functions evaluated while a scene is read. *)

exception Exhausted

(* the steps left; one budget for the process, which reads one scene at a time *)
let left = ref max_int

let start n = left := n

let take n =
  if n > !left then begin
    left := -1;
    raise Exhausted
  end
  else left := !left - n

let loops v = if Float.is_nan v || v < 0. then 1 else if v >= 1e15 then max_int else int_of_float v + 1
