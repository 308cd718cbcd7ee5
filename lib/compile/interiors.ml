(* The interiors a ray starts in: the objects whose box and inside hold its origin. *)

let holds stack (o : Compiled.obj) p = Pov_box.contains o.pbox p && Shape.inside stack o.shape p
let at (holders : Compiled.obj array) stack p = Array.fold_left (fun acc (o : Compiled.obj) -> if holds stack o p then o.iid :: acc else acc) [] holders

(* the robust mode's order: by the volume of the interior's object's box, largest (an unbounded
   one) entered first *)
let innermost_first (objects : Compiled.obj array) ids =
  let volume id = let b = objects.(id).pbox in if Array.length b = 0 then infinity else b.(3) *. b.(4) *. b.(5) in
  List.stable_sort (fun a b -> Float.compare (volume a) (volume b)) ids
