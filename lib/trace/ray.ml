(* A ray and what it carries. *)

type kind = Camera | Reflected | Transmitted | Continued | Shadow

type t = { origin : Vec.t; dir : Vec.t; kind : kind; level : int; weight : float; interiors : int list; mirrored : bool }

let start ~level ~weight ~interiors ~continued origin dir =
  { origin; dir; kind = (if continued then Continued else Camera); level; weight; interiors; mirrored = false }
