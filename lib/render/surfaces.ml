(* The texture at a hit: a mesh face may carry its own, and a ray meeting the surface from inside
   sees the interior texture if there is one. *)

let at (obj : Compiled.obj) part =
  let t = Shape.face_texture obj part in
  if t >= 0 then obj.face_texs.(t) else obj.tex

let seen (obj : Compiled.obj) part ~inside = match obj.inner_tex with Some t when inside -> t | Some _ | None -> at obj part

(* Search_Blend_Map: the last entry from its value on, else the first whose value is not below [v]
   and the one before it; that entry alone on its value, or when it is the first *)
let around (values : float array) v =
  let last = Array.length values - 1 in
  if v >= values.(last) then (last, last)
  else
    let rec go i = if v > values.(i) then go (i + 1) else i in
    let c = go 0 in
    if v = values.(c) || c = 0 then (c, c) else (c - 1, c)
