(* Float.min and Float.max in line. Between two numbers (not NaN) the sign bit only decides between
   +0 and −0, which 1/x tells apart; with a NaN the standard library's own functions decide. *)

let[@inline] negative_zero x = x = 0. && 1. /. x < 0.

let[@inline] max (x : float) y =
  if x <> x || y <> y then Float.max x y else if y > x || (y = x && negative_zero x && not (negative_zero y)) then y else x

let[@inline] min (x : float) y =
  if x <> x || y <> y then Float.min x y else if y < x || (y = x && negative_zero y && not (negative_zero x)) then y else x

let[@inline] max3 (c : Rgb.t) = max c.r (max c.g c.b)
