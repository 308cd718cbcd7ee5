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

(* CSG::Determine_Textures: the textures of the members of [c] that [p] lies in, in member order,
   each CSG member's own found the same way; those found at one level weighed equally (a
   difference: its first member's alone) *)
let rec around_point stack (sc : Compiled.t) (c : Compiled.obj) (p : Vec.t) : (float * Compiled.texture) list =
  (* a member's texture is its object's *)
  let own (m : Compiled.member) =
    let m = sc.objects.(m.id) in
    match m.shape with
    | Csg _ -> around_point stack sc m p
    | _ -> ( match m.tex with Cutaway -> [] | t -> [ (1., t) ])
  in
  match c.shape with
  | Csg { members; _ } when c.difference ->
      if Array.length members > 0 && Shape.inside_member stack members.(0) p then own members.(0) else []
  | Csg { members; _ } ->
      let found = List.concat_map (fun m -> if Shape.inside_member stack m p then own m else []) (Array.to_list members) in
      let w = Precision.f32 (1. /. Float.max (float_of_int (List.length found)) 1.) in
      List.map (fun (_, t) -> (w, t)) found
  | _ -> []

let cutaway stack (sc : Compiled.t) (obj : Compiled.obj) p =
  match obj.shape with
  | Blob b ->
      (* Blob::Determine_Textures: the components' own textures, the blob's (last) for the others *)
      let own = Array.length obj.face_texs - 1 in
      List.map (fun (w, t) -> (w, obj.face_texs.(if t < 0 then own else t))) (Blob.weights b p)
  | _ -> around_point stack sc sc.objects.(obj.top) p
