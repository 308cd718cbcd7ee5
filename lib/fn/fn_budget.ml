(* The step budget of functions evaluated while a scene is read. *)

exception Exhausted

(* the steps left; one budget for the process, which reads one scene at a time *)
let left = ref max_int

let start n = left := n

let take n =
  let r = !left - n in
  left := r;
  if r < 0 then raise Exhausted
