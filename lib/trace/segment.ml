(* Along a ray: an interior's fade. *)

open Compiled

let[@inline] through (kind : Ray.kind) obj interiors depth c =
  let fades =
    match kind with
    | Shadow -> Optics.fades obj && obj.interior.fade_power > 0. && List.mem obj.iid interiors
    | Camera | Reflected | Transmitted | Continued -> Optics.fades obj && List.mem obj.iid interiors
  in
  if fades then Optics.fade obj depth c else c
