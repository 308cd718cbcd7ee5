(* CSG as POV-Ray builds it: inversion by De Morgan's rule, and how an object as read enters the
   scene, a union dissolved into its members and any other CSG kept whole (docs/povray-rules.md §16). *)

open Reader

(* §16.3, Invert_Object and Invert_CSG_Object: a primitive's own Invert changes it where it has
   one (a plane turns over, its normal and distance negated; a quadric negates its coefficients; a
   julia fractal toggles its own flag), and sets POV-Ray's INVERTED_FLAG as its traits say (every
   shape but the plane, the julia fractal, and those whose Invert does nothing: polygon, bicubic
   patch, parametric); a CSG inverts every member and morphs by De Morgan's rule: an inverted
   union or merge is an intersection, an inverted intersection a merge. A light has no geometry to
   invert. *)
let rec invert (o : V.obj) : V.obj =
  match o.shape with
  | Prim s ->
      let shape : Scene.shape =
        match s with
        | Plane { normal; offset; trans } -> Plane { normal = Vec.neg normal; offset = -.offset; trans }
        | Quadric q -> Quadric (Quadric.invert q)
        | Julia f -> Julia (Julia.invert f)
        | _ -> s
      in
      let inverted = if (Shape_kind.of_shape s).inverse_flag then not o.inverted else o.inverted in
      { o with shape = Prim shape; inverted }
  | Csg { members; _ } when List.for_all (function V.Member_light _ -> true | V.Member_obj _ -> false) members ->
      o (* lights only (a light in object position): nothing to invert *)
  | Csg { kind = (Clipped | Bounded | Boxed) as kind; members = V.Member_obj c :: clips; split; box } ->
      (* the object is inverted, its clip or bounding objects are not; the flag (POV-Ray's, on
         the object) leaves it out of an enclosing intersection's box *)
      { o with shape = Csg { kind; members = V.Member_obj (invert c) :: clips; split; box }; inverted = not o.inverted }
  | Csg { kind = (Union | Merge | Intersection | Clipped | Bounded | Boxed) as kind; members; split; box } ->
      let kind : Scene.csg_kind = match kind with Union | Merge -> Intersection | Intersection | Clipped | Bounded | Boxed -> Merge in
      let members = List.map (function V.Member_obj c -> V.Member_obj (invert c) | V.Member_light _ as l -> l) members in
      (* the CSG keeps an inverted flag too: an enclosing intersection leaves it out of its box;
         the CSG it morphs into keeps its box (Morph copies the object) *)
      { o with shape = Csg { kind; members; split; box }; inverted = not o.inverted }

(* §2.7: every object gets a texture and an interior; a legacy finish ior (its top layer's) goes
   into the interior. *)
let resolved st (o : V.obj) =
  let texture = match o.texture with Some t -> t | None -> Scene.Layers [ st.default_texture ] in
  let interior = match o.interior with Some i -> i | None -> Defaults.interior in
  let top = match texture with Layers (l :: _) -> Some l.finish | Layers [] | Texture_pattern _ | Uv_mapped _ | Material_map _ | Cutaway -> None in
  let interior = match Option.bind top (fun f -> f.legacy_ior) with Some ior -> { interior with ior } | None -> interior in
  let interior = match Option.bind top (fun f -> f.legacy_caustics) with Some caustics -> { interior with caustics } | None -> interior in
  let interior = if interior.ior = 0. then { interior with ior = 1. } else interior in
  (texture, interior)

(* The scene object of [o] with [shape], [texture], [interior_texture], [interior] and
   [no_shadow]; its other flags and place are [o]'s. *)
(* a layer whose normal has no pattern: only #default's may, and it must not reach an object *)
let rec patternless (t : Scene.texture) =
  match t with
  | Layers ls -> List.exists (fun (l : Scene.layer) -> match l.normal with Some { npattern = No_pattern; _ } -> true | Some _ | None -> false) ls
  | Texture_pattern { tmap; _ } -> Array.exists (fun (e : Scene.texture_entry) -> patternless e.ttexture) tmap
  | Material_map { materials; _ } -> Array.exists patternless materials
  | Uv_mapped { inner; _ } -> patternless inner
  | Cutaway -> false

let scene_obj (o : V.obj) ?(no_shadow = o.no_shadow) ?(interior_texture = o.interior_texture) shape texture interior : Scene.obj =
  if patternless texture || Option.fold ~none:false ~some:patternless interior_texture then
    Error.raise_at o.oloc "no normal type given: the default normal has no pattern, and this object's texture keeps it";
  {
    Scene.shape;
    texture;
    interior_texture;
    interior;
    no_shadow;
    loc = o.oloc;
    no_image = o.no_image;
    no_reflection = o.no_reflection;
    double_illuminate = o.double_illuminate;
    looks_like = o.looks_like;
    shared_interior = -1;
    uv_mapped = o.uv_mapped;
    difference = o.difference;
  }

let finish_prim st (o : V.obj) shape : Scene.obj =
  let texture, interior = resolved st o in
  scene_obj o shape texture interior

(* A member's interior: its own, or its parent's shared (§16.5). *)
let member_interior (c : V.obj) parent =
  match c.interior with
  | Some i -> ((if i.ior = 0. then { i with Scene.ior = 1. } else i), true)
  | None -> (parent, false)

(* TEXTURED_OBJECT: the object or one of its members has a texture *)
let rec textured (o : V.obj) =
  o.texture <> None || o.interior_texture <> None
  || match o.shape with Prim _ -> false | Csg { members; _ } -> List.exists (function V.Member_obj c -> textured c | V.Member_light _ -> false) members

(* A CSG kept whole (§16.4, §16.5, §19.1), as Post_Process passes textures down: an object without
   a texture takes its parent's (none, when the parent has none); one still without is given the
   default texture, unless a member of it has a texture or its parent is an intersection with
   cutaway_textures: then it has none, and shows the textures around it ([Cutaway]). Every member
   shares the parent's interior unless it has its own; the parent's no_shadow goes to every member
   (only the top level's is ever tested); lights join the scene's lights. *)
let rec kept_obj st ~texture ~cut_parent ?interior_texture ~interior (o : V.obj) : Scene.obj =
  let interior_texture = match o.interior_texture with Some _ -> o.interior_texture | None -> interior_texture in
  let texture = match o.texture with Some _ -> o.texture | None -> texture in
  let texture = match texture with Some _ -> texture | None -> if textured o || cut_parent then None else Some (Scene.Layers [ st.default_texture ]) in
  let shown = match texture with Some t -> t | None -> Scene.Cutaway in
  match o.shape with
  | Prim shape -> scene_obj o ~interior_texture shape shown interior
  | Csg { kind; members; split = _; box } ->
      let cut_parent = kind = Intersection && o.cutaway in
      let members =
        List.filter_map
          (function
            | V.Member_light l -> count_object st o.oloc; st.lights <- l :: st.lights; None
            | V.Member_obj c ->
                let c = match c.texture with Some _ -> c | None -> { c with uv_mapped = c.uv_mapped || o.uv_mapped } in
                let interior, own_interior = member_interior c interior in
                (* §16.5: the flags pass down to every member *)
                let c =
                  {
                    c with
                    no_shadow = c.no_shadow || o.no_shadow;
                    no_image = c.no_image || o.no_image;
                    no_reflection = c.no_reflection || o.no_reflection;
                    cutaway = c.cutaway || o.cutaway;
                  }
                in
                Some { Scene.mobj = kept_obj st ~texture ~cut_parent ?interior_texture ~interior c; inverted = c.inverted; own_interior })
          members
      in
      (* §16.4: a union whose members all have no_shadow has it too *)
      let no_shadow =
        o.no_shadow
        || (match kind with Union -> members <> [] && List.for_all (fun (m : Scene.member) -> m.mobj.no_shadow) members | Merge | Intersection | Clipped | Bounded | Boxed -> false)
      in
      scene_obj o ~no_shadow ~interior_texture (Csg { kind; members; box }) shown interior

(* The object under its clipped_by and bounded_by wrappers: what POV-Ray's object is. *)
let rec core (o : V.obj) =
  match o.shape with Csg { kind = Clipped | Bounded | Boxed; members = V.Member_obj c :: _; _ } -> core c | Prim _ | Csg _ -> o

(* The clip or bounding objects of [o]: the members after the first of its wrapper of [kind],
   looked for through its other wrappers. *)
let rec wrapped kind (o : V.obj) =
  match o.shape with
  | Csg { kind = k; members = _ :: rest; _ } when k = kind -> rest
  | Csg { kind = Clipped | Bounded | Boxed; members = V.Member_obj c :: _; _ } -> wrapped kind c
  | Prim _ | Csg _ -> []

let clip_objects o = wrapped Scene.Clipped o
let bound_objects o = wrapped Scene.Bounded o

let wrap kind (o : V.obj) objs =
  if objs = [] then o
  else
    match o.shape with
    | Csg { kind = k; members; split; box } when k = kind -> { o with shape = Csg { kind; members = members @ objs; split; box } }
    | Prim _ | Csg _ ->
        let inner = { o with texture = None; interior = None; no_shadow = false; linked = false } in
        { o with shape = Csg { kind; members = V.Member_obj inner :: objs; split = false; box = None }; inverted = false }

(* PATCH_OBJECT, which CSG inherits from its members: a shape without an inside (a triangle, a
   mesh without inside_vector, a bicubic patch) *)
let rec patch (o : V.obj) =
  match o.shape with
  | Prim (Mesh { mesh; _ }) -> mesh.inside_vector = None
  | Prim s -> (Shape_kind.of_shape s).patch
  | Csg { members; _ } -> List.exists (function V.Member_obj c -> patch c | V.Member_light _ -> false) members

(* Link_To_Frame keeps the bounding objects of a top-level union, intersection or merge (a text
   object is a union of its letters), of an infinite quadric (one without Automatic_Bounds) and of
   [poly]; any other object's are removed with a warning, their box staying the object's box. *)
let bounds_kept (o : V.obj) =
  match (core o).shape with
  | Csg { kind = Union | Merge | Intersection; _ } -> true
  | Prim (Quadric q) -> q.box_lenx >= 2e10 || q.box_leny >= 2e10 || q.box_lenz >= 2e10
  | Prim (Poly _) -> true
  | Csg { kind = Clipped | Bounded | Boxed; _ } | Prim _ -> false

let rec unbound st (o : V.obj) : V.obj =
  match o.shape with
  | Csg { kind = Bounded; members = V.Member_obj c :: bs; split; box } when not (bounds_kept c) ->
      warn st o.oloc "Unnecessary bounding object removed.";
      { o with shape = Csg { kind = Boxed; members = V.Member_obj (unbound st c) :: bs; split; box } }
  | Csg { kind = (Clipped | Bounded) as kind; members = V.Member_obj c :: rest; split; box } ->
      { o with shape = Csg { kind; members = V.Member_obj (unbound st c) :: rest; split; box } }
  | Prim _ | Csg _ -> o

(* A finite union's box: its members' boxes are all finite (no plane, no infinite quadric, no poly) *)
let rec finite (o : V.obj) =
  match o.shape with
  | Prim (Plane _) -> false
  | Prim (Quadric q) -> q.box_lenx < 2e10 && q.box_leny < 2e10 && q.box_lenz < 2e10
  | Prim (Poly _) -> false (* Poly::Compute_BBox: BOUND_HUGE *)
  | Prim _ -> true
  | Csg { kind = Union | Merge; members; _ } -> List.for_all (function V.Member_obj c -> finite c | V.Member_light _ -> true) members
  | Csg { kind = Intersection | Clipped | Bounded | Boxed; members; _ } ->
      List.exists (function V.Member_obj c -> finite c | V.Member_light _ -> false) members

(* An object entering the scene (§16.4, §16.5): a union that may be split is dissolved, its members
   without a texture or interior take the union's, and its no_shadow goes to every member; its
   lights join the scene's. Another CSG enters whole. An inverted primitive enters as an
   intersection of itself alone, which has the same surface and the negated Inside (§16.3). *)
let rec enter ~shared st (o : V.obj) =
  let o = unbound st o in
  match o.shape with
  | Prim shape when not o.inverted ->
      count_object st o.oloc;
      st.objects <- { (finish_prim st o shape) with shared_interior = shared } :: st.objects
  | Prim _ ->
      (* an inverted primitive: the intersection holds its texture and interior, so the camera's
         interior list and the hits name the same interior, as for POV-Ray's one object *)
      let m = V.Member_obj { o with texture = None; interior_texture = None; interior = None } in
      enter ~shared st { o with shape = Csg { kind = Intersection; members = [ m ]; split = false; box = None }; inverted = false }
  | Csg { kind = Union; members = ms; split = true; _ } ->
      (* the union's interior, its own or the one it shares, is its members' *)
      let union_interior =
        if shared >= 0 then shared
        else begin
          st.split_unions <- st.split_unions + 1;
          st.split_unions
        end
      in
      List.iter
        (function
          | V.Member_light l -> count_object st o.oloc; st.lights <- l :: st.lights
          | V.Member_obj c ->
              enter ~shared:(if c.interior = None then union_interior else -1) st
                {
                  c with
                  texture = (match c.texture with Some _ -> c.texture | None -> o.texture);
                  (* Post_Process: a member that takes the parent's texture takes its uv_mapping *)
                  uv_mapped = (match c.texture with Some _ -> c.uv_mapped | None -> c.uv_mapped || o.uv_mapped);
                  interior_texture = (match c.interior_texture with Some _ -> c.interior_texture | None -> o.interior_texture);
                  interior = (match c.interior with Some _ -> c.interior | None -> o.interior);
                  no_shadow = c.no_shadow || o.no_shadow;
                  no_image = c.no_image || o.no_image;
                  no_reflection = c.no_reflection || o.no_reflection;
                  looks_like = c.looks_like || o.looks_like;
                })
        ms
  | Csg { kind = Union | Merge | Intersection | Clipped | Bounded | Boxed; members = _; split = _; box = _ } ->
      (match o.shape with
      | Csg { kind = Bounded; members = V.Member_obj ({ shape = Csg { kind = Union; members = ms; _ }; _ } as u) :: _; _ } when finite u && ms <> [] ->
          warn st o.oloc "CSG union unnecessarily bounded."
      | Prim _ | Csg _ -> ());
      count_object st o.oloc;
      let _, interior = resolved st o in
      let obj = { (kept_obj st ~texture:None ~cut_parent:false ~interior o) with shared_interior = shared } in
      st.objects <- obj :: st.objects

let add_object st o = enter ~shared:(-1) st o
