(* Three-channel colours, stored unboxed. *)

type t = { r : float; g : float; b : float }

let[@inline] make r g b = { r; g; b }
let black = { r = 0.; g = 0.; b = 0. }
let white = { r = 1.; g = 1.; b = 1. }
let grey v = { r = v; g = v; b = v }
let[@inline] add a c = { r = a.r +. c.r; g = a.g +. c.g; b = a.b +. c.b }
let[@inline] mul a c = { r = a.r *. c.r; g = a.g *. c.g; b = a.b *. c.b }
let[@inline] scale s a = { r = s *. a.r; g = s *. a.g; b = s *. a.b }
let[@inline] max3 c = Float.max c.r (Float.max c.g c.b)
let[@inline] intensity c = (0.297 *. c.r) +. (0.589 *. c.g) +. (0.114 *. c.b)
let is_zero c = c.r = 0. && c.g = 0. && c.b = 0.
