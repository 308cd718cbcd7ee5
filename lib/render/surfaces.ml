(* The surface at a hit: a mesh face may carry its own texture. *)

let at (obj : Compiled.obj) part =
  let t = Shape.face_texture obj part in
  if t >= 0 then obj.face_surfs.(t) else obj.surf
