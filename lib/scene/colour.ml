(* Five-channel colours: red, green, blue, filter, transmit. *)

type t = { red : float; green : float; blue : float; filter : float; transmit : float }

let black = { red = 0.; green = 0.; blue = 0.; filter = 0.; transmit = 0. }

let of_array a =
  let g i = if i < Array.length a then a.(i) else 0. in
  { red = g 0; green = g 1; blue = g 2; filter = g 3; transmit = g 4 }

let rgb c = { Rgb.r = c.red; g = c.green; b = c.blue }

let transmitted c =
  { Rgb.r = (c.red *. c.filter) +. c.transmit; g = (c.green *. c.filter) +. c.transmit; b = (c.blue *. c.filter) +. c.transmit }
