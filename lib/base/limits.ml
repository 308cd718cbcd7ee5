(* The depths a shape accepts (docs/povray-rules.md §2.1). POV-Ray's are fixed lengths, which is why a
   scene's look depends on its size; the robust mode drops them and relies on moving secondary-ray
   origins off the surface by a bound on the hit point's floating-point error instead. *)

type t = { near : float; far : float; tangent : float; close : float }

let pov = { near = 1e-6; far = 1e7; tangent = 1e-10; close = 1e-6 }
(* a box's side ties too are decided exactly: a fixed length would be a different share of a box
   at another scale *)
let robust = { near = 0.; far = infinity; tangent = 0.; close = 0. }
