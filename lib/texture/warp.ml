(* Warps of pattern space (warps.cpp). *)

let classic_turb (ws : Scene.warp list) =
  let rec last = function [] -> None | [ Scene.Classic_turb t ] -> Some t | _ :: rest -> last rest in
  last ws

let point (ws : Scene.warp list) (pat : Scene.pattern) (p : Vec.t) =
  List.fold_left
    (fun p (w : Scene.warp) ->
      match w with
      | Transform_warp t -> Transform.inv_point t p
      | Classic_turb _ when (match pat with Marble | Wood -> true | _ -> false) -> p
      | _ -> failwith "Warp.point: not written yet")
    p ws
