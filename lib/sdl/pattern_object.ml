(* The object of an object pattern (parstxtr.cpp OBJECT_TOKEN in Parse_Pattern, Parse_Bound_Clip):
   Parse_Object as often as an object follows, then translate, rotate, scale, transform and matrix
   moving every object read, then the check that there was one. *)

open Reader

(* The scene object of [o] kept whole, as Csg_build keeps a CSG, but outside the scene: a light
   in a CSG is no light of the scene's (it has no inside), and an inverted primitive becomes the
   intersection of itself alone, whose Inside is the negated one (§16.3). Textures and interiors
   are those Csg_build would give; only the shapes matter to the Inside test. *)
let rec scene_obj st (o : V.obj) : Scene.obj =
  let texture = match o.texture with Some t -> t | None -> Scene.Layers [ st.default_texture ] in
  let interior = match o.interior with Some i -> i | None -> Defaults.interior in
  let made shape = Csg_build.scene_obj o shape texture interior in
  let member (c : V.obj) = { Scene.mobj = scene_obj st { c with inverted = false }; inverted = c.inverted; own_interior = c.interior <> None } in
  match o.shape with
  | Prim shape when not o.inverted -> made shape
  | Prim _ -> made (Csg { kind = Intersection; members = [ member o ]; box = None })
  | Csg { kind; members; split = _; box } ->
      made (Csg { kind; members = List.filter_map (function V.Member_obj c -> Some (member c) | V.Member_light _ -> None) members; box })

let parse st loc : Scene.object_test =
  let rec objects acc = match st.read_object st with Some o -> objects (o :: acc) | None -> List.rev acc in
  let objs = nest st loc (fun () -> objects []) in
  let rec moves objs =
    match peek st with
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
        let op = Expr.parse_op st in
        moves (List.map (Object_value.move_obj op) objs)
    | _ -> objs
  in
  let objs = moves objs in
  (* Parse_Bound_Clip: the transforms are read before it checks that an object came *)
  if objs = [] then unexpected st "an object or object identifier in the object pattern";
  match objs with
  | [ o ] ->
      let obj = scene_obj st o in
      { inside = Inside_test.of_object obj; shown = String.concat " " (List.filter (( <> ) "") (List.map String.trim (String.split_on_char '\n' (Dump.obj obj)))) }
  | [] | _ :: _ :: _ ->
      (* parstxtr.cpp: the pattern has room for one object *)
      Error.raise_at (peek_loc st) "object or object identifier expected: an object pattern takes exactly one object, %d were written" (List.length objs)
