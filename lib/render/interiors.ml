(* The interiors a ray starts in: the objects whose box and inside hold its origin. *)

let holds stack (o : Compiled.obj) p = Pov_box.contains o.pbox p && Shape.inside stack o.shape p
let at (holders : Compiled.obj array) stack p = Array.fold_left (fun acc (o : Compiled.obj) -> if holds stack o p then o.iid :: acc else acc) [] holders
