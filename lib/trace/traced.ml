(* The colour a ray brings back. *)

type t = { r : float; g : float; b : float; tr : float }

let black = { r = 0.; g = 0.; b = 0.; tr = 0. }
