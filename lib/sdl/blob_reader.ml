(* The reader of blob (Parse_Blob, Parse_Blob_Element_Mods of parser/parse.cpp), and the blob's
   own object modifiers. *)

open Token
open Reader
module V = Value

(* One component's modifiers up to its closing brace: transforms move it (and the texture it
   has so far), texture/pigment/normal/finish give it a texture of its own. *)
let component_mods st (c : Blob.component) (tex : Scene.texture option) =
  let edit loc tex f =
    match tex with
    | None -> Some (Scene.Layers [ f st.default_texture ])
    | Some (Scene.Layers (top :: below)) -> Some (Scene.Layers (f top :: below))
    | Some (Layers []) -> tex
    | Some (Texture_pattern _ | Uv_mapped _ | Material_map _ | Cutaway) -> Error.raise_at loc "cannot layer over a patterned texture"
  in
  let moved tex op = Option.map (fun t -> Place.texture t op) tex in
  let rec loop (c : Blob.component) tex =
    let loc = peek_loc st in
    match peek st with
    | RBrace ->
        advance st;
        (c, tex)
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
        let op = Expr.parse_op st in
        let c =
          match op with
          | Place.Translate v -> Blob.translate_component c v
          | Rotate v -> Blob.rotate_component c v
          | Scale v -> Blob.scale_component c v
          | Transform t -> Blob.transform_component c t
        in
        loop c (moved tex op)
    | Ident "texture" ->
        advance st;
        loop c (Some (Texture_reader.link st loc tex (Texture_reader.parse st)))
    | Ident "pigment" -> advance st; loop c (edit loc tex (fun t -> { t with pigment = Materials.parse_pigment st t.pigment }))
    | Ident "finish" -> advance st; loop c (edit loc tex (fun t -> { t with finish = Materials.parse_finish st t.finish }))
    | Ident "normal" -> advance st; loop c (edit loc tex (fun t -> { t with normal = Some (Materials.parse_normal st t.normal) }))
    | _ -> unexpected st "a blob component modifier or '}'"
  in
  loop c tex

(* the radius of a sphere or cylinder component, its comma and the optional [strength] keyword
   that comes before the strength *)
let radius_before_strength st =
  let radius = Expr.parse_float st in
  skip_comma st;
  ignore (accept_ident st "strength");
  radius

let parse st =
  (* the components are kept last written first, as POV-Ray links them *)
  let rec items threshold comps texs =
    let loc = peek_loc st in
    match peek st with
    | Ident "threshold" ->
        advance st;
        items (Expr.parse_float st) comps texs
    | Ident "component" ->
        (* the old syntax: component strength, radius, centre *)
        advance st;
        let strength = Expr.parse_float st in
        skip_comma st;
        let radius = Expr.parse_float st in
        skip_comma st;
        let centre = Expr.parse_vector st in
        items threshold (Blob.sphere_component ~centre ~radius ~strength :: comps) texs
    | Ident "sphere" ->
        advance st;
        open_block st "sphere";
        let centre = Expr.parse_vector st in
        skip_comma st;
        let radius = radius_before_strength st in
        let strength = Expr.parse_float st in
        let c, tex = component_mods st (Blob.sphere_component ~centre ~radius ~strength) None in
        add threshold c tex comps texs
    | Ident "cylinder" -> (
        advance st;
        open_block st "cylinder";
        let base = Expr.parse_vector st in
        skip_comma st;
        let apex = Expr.parse_vector st in
        skip_comma st;
        let radius = radius_before_strength st in
        let sloc = peek_loc st in
        let strength = Expr.parse_float st in
        match Blob.cylinder_component ~base ~apex ~radius ~strength with
        | None -> Error.raise_at sloc "Degenerate cylindrical component in blob."
        | Some c ->
            let c, tex = component_mods st c None in
            add threshold c tex comps texs)
    | _ ->
        if comps = [] then Error.raise_at loc "Need at least one component in a blob.";
        (threshold, comps, List.rev texs)
  and add threshold c tex comps texs =
    match tex with
    | None -> items threshold (c :: comps) texs
    | Some t -> items threshold (Blob.with_texture c (List.length texs) :: comps) (t :: texs)
  in
  let threshold, components, textures = items 1.0 [] [] in
  Scene.Blob
    { blob = { components; threshold; sturm = false; hierarchy = true; trans = None; box = None }; textures = Array.of_list textures }

let set (o : V.obj) f =
  match o.shape with Prim (Blob { blob; textures }) -> { o with shape = Prim (Blob { blob = f blob; textures }) } | Prim _ | Csg _ -> o

(* the hierarchy is built by Make_Blob: the flag changes nothing once the blob is set up *)
let set_hierarchy on o = set o (fun b -> if b.box = None then { b with hierarchy = on } else b)

(* Make_Blob after the object's modifiers: its box (Compute_BBox); a clipped blob is the first
   member of its clip *)
let rec finish (o : V.obj) =
  match o.shape with
  | Prim (Blob { blob; textures }) -> { o with shape = Prim (Blob { blob = Blob.finish blob; textures }) }
  | Csg ({ kind = Clipped; members = V.Member_obj m :: rest; _ } as c) -> { o with shape = Csg { c with members = V.Member_obj (finish m) :: rest } }
  | Prim _ | Csg _ -> o
