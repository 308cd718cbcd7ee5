(* Objects as read (Value.obj), before they enter the scene: a new one, and what the modifiers
   that reach every member do to one (docs/povray-rules.md §14.7, §15.5, §16.5). *)

module V = Value

let new_obj_of shape loc =
  {
    V.shape;
    texture = None;
    interior_texture = None;
    uv_mapped = false;
    difference = false;
    cutaway = false;
    interior = None;
    no_shadow = false;
    oloc = loc;
    no_image = false;
    no_reflection = false;
    double_illuminate = false;
    looks_like = false;
    inverted = false;
    linked = false;
  }

let new_obj shape loc = new_obj_of (V.Prim shape) loc

(* CSG::Compute_BBox of a union or merge when it is built: its members' POV-Ray boxes as they are
   then (a member CSG's own box, a primitive's as compiled; a primitive that cannot be compiled
   is no member of the compiled CSG either). A member CSG without a box of its own leaves the
   union's to be made when it is compiled. *)
let built_box (kind : Scene.csg_kind) members =
  let exception Unknown in
  match kind with
  | Union | Merge -> (
      let box = function
        | V.Member_light _ -> None
        | V.Member_obj { shape = Prim s; _ } -> Option.map Shape.pov_box (Shape.compile ~iso_slot:0 s)
        | V.Member_obj { shape = Csg { box = Some b; _ }; _ } -> Some b
        | V.Member_obj { shape = Csg { box = None; _ }; _ } -> raise Unknown
      in
      try Some (Csg.union_box (List.filter_map box members)) with Unknown -> None)
  | Intersection | Clipped | Bounded | Boxed -> None

let new_csg kind members ~split loc = new_obj_of (V.Csg { kind; members; split; box = built_box kind members }) loc

let move_shape op s = Place.shape s op

(* §14.8: a light's centre and point_at move as points; the direction between them is taken
   when the scene is compiled *)
let move_light op (l : Scene.light) =
  let t = Place.op_transform op in
  { l with position = Transform.point t l.position; point_at = Transform.point t l.point_at }

(* §14.7: an object's texture, if it has one yet, moves with it; members' textures with them *)
let rec move_obj op (o : V.obj) =
  (* an object's uv_mapping keeps its textures where they are (the members' move) *)
  let moved t = if o.uv_mapped then t else Option.map (fun t -> Place.texture t op) t in
  let texture = moved o.texture and interior_texture = moved o.interior_texture in
  match o.shape with
  | Prim s -> { o with shape = Prim (move_shape op s); texture; interior_texture }
  | Csg c -> { o with shape = Csg { c with members = List.map (move_member op) c.members; box = Place.csg_box c.box op }; texture; interior_texture }

and move_member op = function
  | V.Member_obj o -> V.Member_obj (move_obj op o)
  | V.Member_light l -> V.Member_light (move_light op l)

(* §16.5: double_illuminate on a union is set on every member at once, at any depth *)
let rec set_double_illuminate b (o : V.obj) =
  match o.shape with
  | Prim _ -> { o with double_illuminate = b }
  | Csg c ->
      let member = function V.Member_obj c -> V.Member_obj (set_double_illuminate b c) | V.Member_light _ as m -> m in
      { o with double_illuminate = b; shape = Csg { c with members = List.map member c.members } }

(* IsoSurface::Copy marks the copy (its max_gradient is never reported); a CSG's copy copies its
   members *)
let rec copied (o : V.obj) : V.obj =
  let rec scene_shape : Scene.shape -> Scene.shape = function
    | Isosurface s -> Isosurface (Isosurface.mark_copy s)
    | Csg c -> Csg { c with members = List.map (fun (m : Scene.member) -> { m with mobj = { m.mobj with shape = scene_shape m.mobj.shape } }) c.members }
    | s -> s
  in
  match o.shape with
  | Prim s -> { o with shape = Prim (scene_shape s) }
  | Csg c -> { o with shape = Csg { c with members = List.map (function V.Member_obj m -> V.Member_obj (copied m) | V.Member_light _ as l -> l) c.members } }

(* §15.5: the shapes that take [sturm] (solve with Sturm sequences) among their modifiers, wherever
   it stands, read it as their traits say *)
let sturm (o : V.obj) : Traits.sturm = match o.shape with Prim s -> (Shape_kind.of_shape s).sturm | Csg _ -> No_sturm

let set_sturm on (o : V.obj) =
  let shape : Scene.shape option =
    match o.shape with
    | Prim (Torus t) -> Some (Torus { t with sturm = on })
    | Prim (Prism p) -> Some (Prism { p with sturm = on })
    | Prim (Lathe l) -> Some (Lathe { l with sturm = on })
    | Prim (Sor s) -> Some (Sor { s with sturm = on })
    | Prim (Poly p) -> Some (Poly { p with sturm = on })
    | Prim (Ovus v) -> Some (Ovus { v with sturm = on })
    | Prim (Blob b) -> Some (Blob { b with blob = { b.blob with sturm = on } })
    | Prim _ | Csg _ -> None
  in
  match shape with Some s -> { o with shape = Prim s } | None -> o
