(* The object parser: which object a keyword starts, the primitives read in place, and the
   modifiers every object takes (docs/povray-rules.md §2, §14, §15, §16). *)

open Token
open Reader
open Expr
open Materials
open Object_value
open Csg_build

(* Objects povml does not render yet: inside a union they are reported as "not supported yet". *)
let unsupported_objects = Keywords.words (fun s -> s = Keywords.Object_not_supported)

let show_vec (v : Vec.t) = Printf.sprintf "<%g, %g, %g>" v.x v.y v.z

(* Values povml cannot make yet; a declaration of one is kept as [V.Unsupported]. *)
let unsupported_rvalues =
  [ "normal_map"; "slope_map";
    "media"; "density"; "fog"; "rainbow" ]

let unsupported_rvalue_set = set_of (unsupported_objects @ unsupported_rvalues)

let unsupported_object_set = set_of unsupported_objects

(* A light where an object may stand: a union of the light alone, dissolved into the scene's lights. *)
let light_union l = V.Csg { kind = Union; members = [ V.Member_light l ]; split = true; box = None }

(* An object; a shape whose braces open on an object identifier is a copy of that object with
   the modifiers that follow (Reader.open_shape, POV-Ray's Parse_Object_Id) *)
let rec parse_object st : V.obj =
  let loc = peek_loc st in
  try parse_shape st loc with Object_copy (o, kw) -> parse_object_mods st { (copied o) with oloc = loc } kw

and parse_shape st loc : V.obj =
  match peek st with
  | Ident ("triangle" | "smooth_triangle" as kw) ->
      advance st;
      open_shape st kw;
      let smooth = kw = "smooth_triangle" in
      let p1, p2, p3, ns = Mesh_reader.triangle_corners st ~smooth in
      let shape : Scene.shape =
        match ns with
        | None ->
            if Triangle.flat p1 p2 p3 = None then warn st loc "degenerate triangle; please remove it";
            Triangle { p1; p2; p3 }
        | Some (n1, n2, n3) ->
            (match Triangle.smooth p1 n1 p2 n2 p3 n3 with
            | None | Some (Error ()) -> warn st loc "degenerate triangle; please remove it"
            | Some (Ok _) -> ());
            Smooth_triangle { p1; n1; p2; n2; p3; n3 }
      in
      parse_object_mods st (new_obj shape loc) kw
  | Ident "mesh" ->
      advance st;
      let shape = Mesh_reader.mesh st loc in
      parse_object_mods st (new_obj shape loc) "mesh"
  | Ident "mesh2" ->
      advance st;
      let shape = Mesh_reader.mesh2 st loc in
      parse_object_mods st (new_obj shape loc) "mesh2"
  | Ident "sphere" ->
      advance st;
      open_shape st "sphere";
      let centre = parse_vector st in
      ignore (accept st Comma) (* POV-Ray accepts the comma as optional *);
      let rloc = peek_loc st in
      let radius = parse_float st in
      if radius <= 0. then warn st rloc "sphere radius %g is not positive" radius;
      parse_object_mods st (new_obj (Sphere { centre; radius; trans = None; uv_trans = None }) loc) "sphere"
  | Ident "box" ->
      (* §15.1: the corners are sorted per axis; a flat or empty box is accepted silently *)
      advance st;
      open_shape st "box";
      let a = parse_vector st in
      ignore (accept st Comma);
      let b = parse_vector st in
      let lo_of p q = if p > q then q else p and hi_of p q = if p > q then p else q in
      let lo = Vec.make (lo_of a.x b.x) (lo_of a.y b.y) (lo_of a.z b.z) in
      let hi = Vec.make (hi_of a.x b.x) (hi_of a.y b.y) (hi_of a.z b.z) in
      parse_object_mods st (new_obj (Box { lo; hi; trans = None }) loc) "box"
  | Ident "cylinder" ->
      (* §15.2: cylinder { P1, P2, r [open] } *)
      advance st;
      open_shape st "cylinder";
      let p1 = parse_vector st in
      skip_comma st;
      let p2 = parse_vector st in
      skip_comma st;
      let rloc = peek_loc st in
      let radius = parse_float st in
      let closed = not (accept_ident st "open") in
      if radius = 0. then warn st rloc "cylinder radius is 0: it cannot be seen";
      (match Canonical.cylinder ~p1 ~p2 ~radius ~closed with
      | Some shape -> parse_object_mods st (new_obj shape loc) "cylinder"
      | None -> Error.raise_at loc "degenerate cylinder: its end points %s and %s are the same point" (show_vec p1) (show_vec p2))
  | Ident "cone" ->
      (* §15.3: cone { P1, r1, P2, r2 [open] } *)
      advance st;
      open_shape st "cone";
      let p1 = parse_vector st in
      skip_comma st;
      let r1 = parse_float st in
      skip_comma st;
      let p2 = parse_vector st in
      skip_comma st;
      let r2loc = peek_loc st in
      let r2 = parse_float st in
      let closed = not (accept_ident st "open") in
      if r1 = 0. && r2 = 0. then warn st r2loc "both cone radii are 0: it cannot be seen";
      (match Canonical.cone ~p1 ~r1 ~p2 ~r2 ~closed with
      | Some shape -> parse_object_mods st (new_obj shape loc) "cone"
      | None -> Error.raise_at loc "degenerate cone: its end points %s and %s are the same point" (show_vec p1) (show_vec p2))
  | Ident "disc" ->
      (* §15.4: disc { C, N, R [, H] } *)
      advance st;
      open_shape st "disc";
      let centre = parse_vector st in
      skip_comma st;
      let nloc = peek_loc st in
      let normal = parse_vector st in
      skip_comma st;
      let radius = parse_float st in
      skip_comma st;
      let hole = if float_follows st then parse_float st else 0. in
      if Vec.length normal = 0. then Error.raise_at nloc "degenerate disc normal <0,0,0>";
      parse_object_mods st (new_obj (Canonical.disc ~centre ~normal ~radius ~hole) loc) "disc"
  | Ident "torus" ->
      (* §15.5: torus { R, r } (the comma optional), then its modifiers *)
      advance st;
      open_shape st "torus";
      let major = parse_float st in
      ignore (accept st Comma);
      let minor = parse_float st in
      let shape = Scene.Torus { major; minor; sturm = false; trans = Transform.identity } in
      parse_object_mods st (new_obj shape loc) "torus"
  | Ident "blob" ->
      (* Parse_Blob: threshold and components, then the object's modifiers, then Make_Blob *)
      advance st;
      open_shape st "blob";
      (match peek st with
      | Ident s when (match cur_value st s with Some (V.Object _) -> true | _ -> false) -> (
          (* Parse_Object_Id: an object identifier first makes it object { … } *)
          match cur_value st s with
          | Some (V.Object o) -> advance st; parse_object_mods st { (copied o) with oloc = loc } "blob"
          | _ -> unexpected st "an object identifier")
      | _ ->
          let shape = Blob_reader.parse st in
          Blob_reader.finish (parse_object_mods st (new_obj shape loc) "blob"))
  | Ident ("poly" | "cubic" | "quartic" | "polynomial" as kw) ->
      advance st;
      open_shape st kw;
      let shape =
        match kw with
        | "cubic" -> Shape_reader.poly st ~order:3
        | "quartic" -> Shape_reader.poly st ~order:4
        | "polynomial" -> Shape_reader.polynomial st
        | _ -> Shape_reader.poly st ~order:0
      in
      parse_object_mods st (new_obj shape loc) kw
  | Ident ("polygon" | "quadric" as kw) ->
      advance st;
      open_shape st kw;
      parse_object_mods st (new_obj (if kw = "polygon" then Shape_reader.polygon st loc else Shape_reader.quadric st) loc) kw
  | Ident "height_field" ->
      (* Parse_HField: the image and its options, then the modifiers; the field's blocks are built
         after them (Compute_HField follows Parse_Object_Mods), so [hierarchy] there still counts *)
      advance st;
      let o = parse_object_mods st (new_obj (Hfield_reader.parse st) loc) "height_field" in
      let seal (o : V.obj) = match o.shape with Prim (Height_field h) -> { o with shape = Prim (Height_field { h with field = Hfield.seal h.field }) } | Prim _ | Csg _ -> o in
      (match o.shape with
      | Csg { kind; members = V.Member_obj m :: rest; split; box } -> { o with shape = Csg { kind; members = V.Member_obj (seal m) :: rest; split; box } }
      | Csg _ | Prim _ -> seal o)
  | Ident "superellipsoid" ->
      advance st;
      open_shape st "superellipsoid";
      parse_object_mods st (new_obj (Superq_reader.superellipsoid st) loc) "superellipsoid"
  | Ident "ovus" ->
      advance st;
      open_shape st "ovus";
      parse_object_mods st (new_obj (Superq_reader.ovus st loc) loc) "ovus"
  | Ident "sphere_sweep" ->
      advance st;
      open_shape st "sphere_sweep";
      parse_object_mods st (new_obj (Superq_reader.sphere_sweep st) loc) "sphere_sweep"
  | Ident ("prism" | "lathe" | "sor" as kw) ->
      advance st;
      open_shape st kw;
      let shape = match kw with "prism" -> Spline_reader.prism st loc | "lathe" -> Spline_reader.lathe st loc | _ -> Spline_reader.sor st loc in
      parse_object_mods st (new_obj shape loc) kw
  | Ident "bicubic_patch" ->
      advance st;
      open_shape st "bicubic_patch";
      parse_object_mods st (new_obj (Bicubic_reader.bicubic st loc) loc) "bicubic_patch"
  | Ident "isosurface" ->
      advance st;
      open_shape st "isosurface";
      parse_object_mods st (new_obj (Iso_reader.isosurface st) loc) "isosurface"
  | Ident "julia_fractal" ->
      advance st;
      open_shape st "julia_fractal";
      let shape = Julia_reader.julia st in
      Julia_reader.set_up loc (parse_object_mods st (new_obj shape loc) "julia_fractal")
  | Ident "parametric" ->
      advance st;
      open_shape st "parametric";
      let shape, pre = Parametric_reader.parametric st in
      Parametric_reader.finish pre (parse_object_mods st (new_obj shape loc) "parametric")
  | Ident "text" ->
      (* §15.9: a union of one extruded glyph per character, then the modifiers, which move every
         letter *)
      advance st;
      let text = Text_object.parse st loc in
      parse_object_mods st text "text"
  | Ident "plane" ->
      advance st;
      open_shape st "plane";
      let nloc = peek_loc st in
      let n = parse_vector st in
      ignore (accept st Comma);
      let d = parse_float st in
      (* §2.3: the normal is normalised, the distance is NOT divided by |n| *)
      if Vec.length n = 0. then Error.raise_at nloc "degenerate plane normal <0,0,0>";
      parse_object_mods st (new_obj (Plane { normal = Vec.normalize n; offset = d; trans = None }) loc) "plane"
  | Ident "object" ->
      advance st;
      open_block st "object";
      let iloc = peek_loc st in
      let o =
        match peek st with
        | Ident s when Names.mem object_set s -> parse_object st
        | Ident s -> (
            match cur_value st s with
            | Some (V.Object o) -> advance st; { (copied o) with oloc = loc }
            | Some (V.Light l) -> advance st; { (new_obj_of (light_union l) loc) with oloc = loc }
            | Some (V.Unsupported u) -> unsupported_use iloc s u.what u.at
            | Some v -> Error.raise_at iloc "'%s' is %s, not an object" s (V.kind_name v)
            | None -> if is_keyword s then unexpected st "an object identifier" else unknown_identifier st iloc s)
        | _ -> unexpected st "an object identifier"
      in
      parse_object_mods st o "object"
  | Ident ("union" | "merge" | "intersection" | "difference" as kw) ->
      (* §16.1: the members first, then the CSG's own modifiers; a difference is an intersection
         whose members after the first are inverted. §16.4: a union is dissolved into its members
         when it enters the scene unless split_union is off; its texture, interior and flags go to
         the members that have none *)
      advance st;
      open_block st kw;
      let rec members acc =
        match peek st with
        | Ident "light_source" ->
            (* POV-Ray warns (and keeps the light) in an intersection or difference (§19.1) *)
            if kw = "intersection" || kw = "difference" then
              warn st (peek_loc st) "a light_source (a patch object) is not allowed in an %s; it is kept as a light" kw;
            let m = match parse_light_source st with Lights.Lone l -> V.Member_light l | Shaped o -> V.Member_obj o in
            members (m :: acc)
        | _ when object_follows st ->
            let o = parse_object st in
            (* Parse_CSG warns of a patch object (one without an inside) in an intersection *)
            if (kw = "intersection" || kw = "difference") && patch o then warn st o.oloc "Patch objects not allowed in intersection.";
            members (V.Member_obj o :: acc)
        | _ -> List.rev acc
      in
      let ms = nest st loc (fun () -> members []) in
      if List.length ms < 2 then warn st loc "a %s should have at least two members" kw;
      let ms =
        if kw <> "difference" then ms
        else List.mapi (fun i m -> match m with V.Member_obj o when i > 0 -> V.Member_obj (invert o) | V.Member_obj _ | V.Member_light _ -> m) ms
      in
      let kind : Scene.csg_kind = match kw with "union" -> Union | "merge" -> Merge | _ -> Intersection in
      parse_object_mods st { (new_csg kind ms ~split:(kind = Union) loc) with difference = kw = "difference" } kw
  | Ident "light_source" -> (
      match parse_light_source st with Lights.Lone l -> new_obj_of (light_union l) loc | Shaped o -> o)
  | Ident s -> (
      match cur_value st s with
      | Some (V.Object o) -> advance st; { (copied o) with oloc = loc }
      | Some (V.Light l) -> advance st; new_obj_of (light_union l) loc
      | Some (V.Unsupported u) -> unsupported_use loc s u.what u.at
      | _ -> unexpected st "an object")
  | _ -> unexpected st "an object"

(* A light_source, its looks_like object read by [parse_object] (§19.2). *)
and parse_light_source st = Lights.parse st ~object_:parse_object ~mods:parse_object_mods

(* The modifiers of an object, up to its closing brace. *)
and parse_object_mods st (o : V.obj) what : V.obj =
  (* pigment, normal and finish edit the top layer of the object's texture (the default texture
     when it has none); a patterned texture has no layer to edit *)
  let edit loc (o : V.obj) f =
    match o.V.texture with
    | None -> { o with texture = Some (Scene.Layers [ f st.default_texture ]) }
    | Some (Layers (top :: below)) -> { o with texture = Some (Layers (f top :: below)) }
    | Some (Layers []) -> o
    | Some (Texture_pattern _ | Uv_mapped _ | Material_map _ | Cutaway) -> Error.raise_at loc "cannot layer over a patterned texture"
  in
  let rec loop (o : V.obj) =
    let loc = peek_loc st in
    match peek st with
    | RBrace ->
        if o.texture = None && o.interior_texture <> None then Error.raise_at loc "an interior texture requires an exterior texture";
        advance st;
        o
    | Ident "pigment" -> advance st; loop (edit loc o (fun t -> { t with pigment = parse_pigment st t.pigment }))
    | Ident "finish" -> advance st; loop (edit loc o (fun t -> { t with finish = parse_finish st t.finish }))
    | Ident "normal" -> advance st; loop (edit loc o (fun t -> { t with normal = Some (parse_normal st t.normal) }))
    | Ident "texture" -> advance st; loop { o with texture = Some (Texture_reader.link st loc o.texture (Texture_reader.parse st)) }
    | Ident "cutaway_textures" ->
        advance st;
        (match (core o).shape with
        | Csg { kind = Intersection; _ } -> ()
        | Csg { kind = Union | Merge | Clipped | Bounded | Boxed; _ } | Prim _ -> Error.raise_at loc "cutaway_textures can only be used with intersection and difference");
        loop { o with cutaway = true }
    | Ident "uv_mapping" ->
        advance st;
        if o.texture <> None then Error.raise_at loc "uv_mapping must be specified before texture";
        loop { o with uv_mapped = true }
    | Ident "interior_texture" ->
        advance st;
        open_block st "interior_texture";
        loop { o with interior_texture = Some (Texture_reader.link st loc o.interior_texture (Texture_reader.parse_body st ~close:RBrace)) }
    | Ident "material" ->
        advance st;
        let m = Texture_reader.parse_material st { mtexture = o.texture; minterior_texture = o.interior_texture; minterior = o.interior } in
        loop { o with texture = m.mtexture; interior_texture = m.minterior_texture; interior = m.minterior }
    | Ident "interior" ->
        advance st;
        let base = match o.interior with Some i -> i | None -> Defaults.interior in
        loop { o with interior = Some (parse_interior st base) }
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") -> loop (move_obj (parse_op st) o)
    | Ident "no_shadow" -> advance st; loop { o with no_shadow = true }
    (* §16.6: the flags take an optional boolean; hollow only matters to media, which povml lacks *)
    | Ident "no_image" -> advance st; loop { o with no_image = parse_bool_opt st }
    | Ident "no_reflection" -> advance st; loop { o with no_reflection = parse_bool_opt st }
    | Ident "double_illuminate" -> advance st; loop (set_double_illuminate (parse_bool_opt st) o)
    | Ident "sturm" when sturm o <> No_sturm ->
        advance st;
        let on =
          match sturm o with
          | No_sturm | Sturm_flag -> true
          | Sturm_bool -> parse_bool_opt st (* Bool_Flag(STURM_FLAG, Allow_Float(1.0) > 0) *)
          | Sturm_float -> (not (float_follows st)) || parse_float st > 0. (* Allow_Float(1.0) > 0.0 *)
        in
        loop (set_sturm on o)
    | Ident "hollow" -> advance st; ignore (parse_bool_opt st); loop o
    | Ident "inverse" -> advance st; loop (invert o)
    | Ident "split_union" -> (
        advance st;
        let on = (not (float_follows st)) || parse_float st > 0. (* Allow_Float(1.0) > 0.0 *) in
        (* §16.4: only a union is ever split; POV-Ray accepts the keyword on a merge (a kind of
           union to it) without effect and stops on any other object *)
        match o.shape with
        | Csg ({ kind = Union; _ } as c) -> loop { o with shape = Csg { c with split = on } }
        | Csg { kind = Merge; _ } | Csg { kind = Clipped | Bounded | Boxed; members = V.Member_obj { shape = Csg { kind = Union | Merge; _ }; _ } :: _; _ } ->
            loop o (* a merge, or a clipped or bounded union, is never split *)
        | Csg { kind = Intersection | Clipped | Bounded | Boxed; _ } | Prim _ -> Error.raise_at loc "split_union found in a non-union object")
    | Ident "clipped_by" ->
        (* §15.8: clipped_by { OBJECT … }: the object's hits are kept inside every clip object, and
           so is its Inside. The clip objects move with the object's later transforms; its
           texture, interior and flags stay on the clipped object. [clipped_by { bounded_by }]
           clips by the bounding objects. *)
        advance st;
        open_block st "clipped_by";
        if o.linked && clip_objects o <> [] then Error.raise_at loc "Cannot add clips after linking bounds and clips.";
        let cl, linked =
          match peek st with
          | Ident "bounded_by" ->
              let bloc = peek_loc st in
              advance st;
              if clip_objects o <> [] then Error.raise_at bloc "Cannot link bounds with previous clips.";
              (bound_objects o, true)
          | _ -> (nest st loc (fun () -> bound_clip st "clipped_by"), false)
        in
        close_block st "clipped_by";
        loop { (wrap Clipped o cl) with linked = o.linked || linked }
    | Ident "bounded_by" ->
        (* bounded_by { OBJECT … }: a ray meets the object only if it meets every bounding object
           or starts inside one (Ray_In_Bound), and their box is the object's when it is the
           smaller; [bounded_by { clipped_by }] bounds by the clip objects *)
        advance st;
        open_block st "bounded_by";
        if o.linked && bound_objects o <> [] then Error.raise_at loc "Cannot add bounds after linking bounds and clips.";
        let bs, linked =
          match peek st with
          | Ident "clipped_by" ->
              let cloc = peek_loc st in
              advance st;
              if bound_objects o <> [] then Error.raise_at cloc "Cannot link clips with previous bounds.";
              (clip_objects o, true)
          | _ -> (nest st loc (fun () -> bound_clip st "bounded_by"), false)
        in
        close_block st "bounded_by";
        loop { (wrap Bounded o bs) with linked = o.linked || linked }
    (* What only photon mapping or radiosity reads, which are off unless global_settings turns
       them on (and povml refuses that there): read as POV-Ray reads it (Parse_Object_Mods), and
       nothing changes (trace.cpp tests photonsEnabled before any photon flag). *)
    | Ident "photons" ->
        advance st;
        open_block st "photons";
        let rec items () =
          match peek st with
          | Ident "target" -> advance st; if float_follows st then ignore (parse_float st); items ()
          | Ident ("refraction" | "reflection") -> advance st; ignore (parse_float st); items ()
          | Ident ("pass_through" | "collect") -> advance st; ignore (parse_bool_opt st); items ()
          | _ -> ()
        in
        items ();
        close_block st "photons";
        loop o
    | Ident "radiosity" ->
        advance st;
        Settings.parse_radiosity_importance st;
        loop o
    | Ident "no_radiosity" -> advance st; ignore (parse_bool_opt st); loop o
    | Ident "hierarchy" -> (
        (* a mesh's own bounding hierarchy, which only changes how fast it is traced; a blob's,
           which also decides the order its elements are summed in *)
        advance st;
        let on = parse_bool_opt st in
        match o.shape with
        | Prim (Mesh _) -> loop o
        | Prim (Blob _) -> loop (Blob_reader.set_hierarchy on o)
        | Prim (Height_field h) -> loop { o with shape = Prim (Height_field { h with field = Hfield.with_hierarchy h.field on }) }
        | Prim _ | Csg _ -> Error.raise_at loc "'hierarchy' cannot be used with this object (only with a mesh)")
    | Ident "dtag" ->
        (* a debugging tag, unused by the render *)
        advance st;
        let l = peek_loc st in
        (match parse_expr st with V.String _ -> () | v -> Error.raise_at l "'dtag' needs a string, not %s" (V.kind_name v));
        loop o
    | _ when is_colour_start st ->
        (* a colour written straight in an object: POV-Ray reads it and ignores it *)
        ignore (parse_colour st);
        warn st loc "Quick color belongs in texture. Color ignored.";
        loop o
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s'" s)
    | _ -> unexpected st (Printf.sprintf "an object modifier or '}' closing '%s'" what)
  in
  loop o

(* Parse_Bound_Clip: the objects of a clipped_by or bounded_by block, none textured or without an
   inside, then the transforms that move them all. *)
and bound_clip st what =
  let rec objects acc =
    if object_follows st then begin
      let c = parse_object st in
      if textured c || patch c then Error.raise_at c.oloc "Illegal texture or patch in clip, bound or object pattern.";
      objects (c :: acc)
    end
    else List.rev acc
  in
  let objs = objects [] in
  if objs = [] then unexpected st (Printf.sprintf "an object in %s" what);
  let rec moved objs =
    match peek st with
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
        let op = parse_op st in
        moved (List.map (move_obj op) objs)
    | _ -> objs
  in
  List.map (fun c -> V.Member_obj c) (moved objs)

(* Does an object (a keyword or an identifier of one) come next? *)
and object_follows st =
  match peek st with
  | Ident s when Names.mem object_set s -> true
  | Ident s -> ( match cur_value st s with Some (V.Object _ | V.Light _) -> true | Some (V.Unsupported _) -> true | _ -> Names.mem unsupported_object_set s)
  | _ -> false
