(* The robust mode: where secondary rays leave a surface. *)

let norm_inf (v : Vec.t) = Float.max (Float.abs v.x) (Float.max (Float.abs v.y) (Float.abs v.z))
let error_bound ~shift (o : Vec.t) (p : Vec.t) mag = (0x1p-44 *. (norm_inf o +. norm_inf p +. mag)) +. (0x1p-50 *. shift)

let[@inline] origin (ctx : Context.t) (p : Vec.t) (ng : Vec.t) e (dir : Vec.t) =
  if not ctx.robust then p else if Vec.dot dir ng >= 0. then Vec.madd p e ng else Vec.madd p (-.e) ng
