(* Objects: transforms, the primitives, meshes, unions and light sources (POVRAY-3.7 §2, §14, §16.4). *)

open Token
open Reader
open Expr
open Materials



let move_shape op s = Place.shape s op

(* §14.8: a light's centre and point_at move as points; the direction between them is taken
   when the scene is compiled *)
let move_light op (l : Scene.light) =
  let t = Place.op_transform op in
  { l with position = Transform.point t l.position; point_at = Transform.point t l.point_at }

(* §16.5: double_illuminate on a union is set on every member at once, at any depth *)
let rec set_double_illuminate b (o : V.obj) =
  match o.shape with
  | Prim _ -> { o with double_illuminate = b }
  | Csg c ->
      let member = function V.Member_obj c -> V.Member_obj (set_double_illuminate b c) | V.Member_light _ as m -> m in
      { o with double_illuminate = b; shape = Csg { c with members = List.map member c.members } }

(* §14.7: an object's texture, if it has one yet, moves with it; members' textures with them *)
let rec move_obj op (o : V.obj) =
  let texture = Option.map (fun t -> Place.texture t op) o.texture in
  match o.shape with
  | Prim s -> { o with shape = Prim (move_shape op s); texture }
  | Csg c -> { o with shape = Csg { c with members = List.map (move_member op) c.members }; texture }

and move_member op = function
  | V.Member_obj o -> V.Member_obj (move_obj op o)
  | V.Member_light l -> V.Member_light (move_light op l)

(* §15.5: a torus takes [sturm] (solve with Sturm sequences) among its modifiers, wherever it
   stands; [inverse] is every primitive's (§16.3) *)
let is_torus (o : V.obj) = match o.shape with Prim (Torus _) -> true | Prim _ | Csg _ -> false

let set_sturm (o : V.obj) =
  match o.shape with Prim (Torus t) -> { o with shape = Prim (Torus { t with sturm = true }) } | Prim _ | Csg _ -> o

(* §16.3, Invert_Object and Invert_CSG_Object: a plane turns over (normal and distance negated),
   another primitive toggles its inverted flag, a CSG inverts every member and morphs by De
   Morgan's rule: an inverted union or merge is an intersection, an inverted intersection a merge.
   A light has no geometry to invert. *)
let rec invert (o : V.obj) : V.obj =
  match o.shape with
  | Prim (Plane { normal; offset; trans }) -> { o with shape = Prim (Plane { normal = Vec.neg normal; offset = -.offset; trans }) }
  | Prim (Sphere _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Cone _ | Disc _ | Torus _ | Csg _ | Glyph _) -> { o with inverted = not o.inverted }
  | Csg { members; _ } when List.for_all (function V.Member_light _ -> true | V.Member_obj _ -> false) members ->
      o (* lights only (a light in object position): nothing to invert *)
  | Csg { kind = Clipped; members = V.Member_obj c :: clips; split } ->
      (* the object is inverted, its clip objects are not *)
      { o with shape = Csg { kind = Clipped; members = V.Member_obj (invert c) :: clips; split } }
  | Csg { kind = (Union | Merge | Intersection | Clipped) as kind; members; split } ->
      let kind : Scene.csg_kind = match kind with Union | Merge -> Intersection | Intersection | Clipped -> Merge in
      let members = List.map (function V.Member_obj c -> V.Member_obj (invert c) | V.Member_light _ as l -> l) members in
      (* the CSG keeps an inverted flag too: an enclosing intersection leaves it out of its box *)
      { o with shape = Csg { kind; members; split }; inverted = not o.inverted }

let new_obj_of shape loc =
  {
    V.shape;
    texture = None;
    interior = None;
    no_shadow = false;
    oloc = loc;
    no_image = false;
    no_reflection = false;
    double_illuminate = false;
    looks_like = false;
    inverted = false;
  }
let new_obj shape loc = new_obj_of (V.Prim shape) loc


(* Objects povml does not render yet: inside a union they are reported as "not supported yet". *)
let unsupported_objects =
  [ "polygon"; "prism"; "lathe"; "sor"; "blob"; "height_field";
    "isosurface"; "superellipsoid"; "julia_fractal"; "parametric"; "bicubic_patch"; "ovus"; "quadric"; "cubic";
    "quartic"; "poly"; "sphere_sweep"; "lemon" ]

(* A light source as read: a light alone, or a light with its looks_like object, which is kept
   as a union of the two so that later transforms move both and the scene dissolves it (§19.2). *)
type light_source = Lone of Scene.light | Shaped of V.obj

(* light_source { centre, colour … } (§10.2, §18.2, §18.3, §19.2). radius, falloff and tightness
   need a spotlight or cylinder keyword written before them, point_at one of those or parallel;
   [object_] reads the object of a looks_like. *)
let parse_light_with st ~object_ ~mods =
  let lloc = peek_loc st in
  advance st;
  open_block st "light_source";
  let position = parse_vector st in
  ignore (accept st Comma);
  (* §10.2: the colour after the position; without one the light is black *)
  let colour = if peek st == RBrace || (match peek st with Ident s -> List.mem s [ "shadowless"; "fade_distance"; "fade_power"; "translate" ] | _ -> false) then Rgb.black else parse_rgb st "a light colour" in
  let shaped (l : Scene.light) loc what =
    match l.kind with
    | Spotlight | Cylinder_light -> ()
    | Point_light -> Error.raise_at loc "'%s' needs a spotlight or cylinder light: write 'spotlight' or 'cylinder' before it" what
  in
  let rec loop_with (l : Scene.light) (looks : V.obj option) =
    let loop l = loop_with l looks in
    let loc = peek_loc st in
    match peek st with
    | RBrace -> (
        advance st;
        match looks with
        | None -> Lone l
        | Some o ->
            Shaped (new_obj_of (V.Csg { kind = Union; members = [ V.Member_light l; V.Member_obj o ]; split = true }) lloc))
    (* §19.2: the object is written about the origin and moved to the centre, then its own
       modifiers apply; it never casts a shadow *)
    | Ident "looks_like" ->
        if looks <> None then Error.raise_at loc "a light_source takes only one looks_like";
        advance st;
        open_block st "looks_like";
        let o = move_obj (Place.Translate l.position) (object_ st) in
        let o = mods st o "looks_like" in
        loop_with l (Some { o with no_shadow = true; looks_like = true })
    | Ident "shadowless" -> advance st; loop { l with shadowless = true }
    | Ident "fade_distance" -> advance st; loop { l with fade_distance = parse_float st }
    | Ident "fade_power" -> advance st; loop { l with fade_power = parse_float st }
    (* §18.2: the kind keyword resets radius, falloff and tightness to its defaults where it stands *)
    | Ident "spotlight" ->
        advance st;
        loop { l with kind = Spotlight; radius = cos (30. *. Float.pi /. 180.); falloff = cos (45. *. Float.pi /. 180.); tightness = 0. }
    | Ident "cylinder" -> advance st; loop { l with kind = Cylinder_light; radius = 0.75; falloff = 1.; tightness = 0.; parallel = true }
    | Ident "parallel" -> advance st; loop { l with parallel = true }
    | Ident "point_at" ->
        (match l.kind with
        | Spotlight | Cylinder_light -> ()
        | Point_light ->
            if not l.parallel then
              Error.raise_at loc "'point_at' needs a spotlight, cylinder or parallel light: write 'spotlight', 'cylinder' or 'parallel' before it");
        advance st;
        loop { l with point_at = parse_vector st }
    | Ident "radius" ->
        shaped l loc "radius";
        advance st;
        let r = parse_float st in
        loop { l with radius = (match l.kind with Spotlight -> cos (r *. Float.pi /. 180.) | Cylinder_light | Point_light -> r) }
    | Ident "falloff" ->
        shaped l loc "falloff";
        advance st;
        let r = parse_float st in
        loop { l with falloff = (match l.kind with Spotlight -> cos (r *. Float.pi /. 180.) | Cylinder_light | Point_light -> r) }
    | Ident "tightness" -> shaped l loc "tightness"; advance st; loop { l with tightness = parse_float st }
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
        let op = parse_op st in
        loop_with (move_light op l) (Option.map (move_obj op) looks)
    | Ident ("color" | "colour" | "rgb") -> loop { l with colour = parse_rgb st "a light colour" }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a light_source" s)
    | _ -> unexpected st "a light_source keyword or '}'"
  in
  loop_with
    {
      Scene.position;
      colour;
      shadowless = false;
      fade_distance = 0.;
      fade_power = 0.;
      kind = Point_light;
      parallel = false;
      point_at = Vec.make 0. 0. 1.;
      radius = 0.;
      falloff = 0.;
      tightness = 0.;
    }
    None

let f32 x = Int32.float_of_bits (Int32.bits_of_float x)

(* Vertex normals: normalised; a zero normal becomes <1,0,0> with a warning (§2.6). *)
let unit_normal st loc (n : Vec.t) =
  if Vec.length n = 0. then begin
    warn st loc "zero-length normal replaced by <1,0,0>";
    Vec.make 1. 0. 0.
  end
  else Vec.normalize n

let comma st = ignore (accept st Comma)

(* §15.9: a string argument of text (the font file, the string), located when missing *)
let text_string st what =
  let l = peek_loc st in
  match peek st with
  | Comma | RBrace -> Error.raise_at l "text needs %s here" what
  | _ -> (
      match Expr.parse_expr st with
      | V.String s -> s
      | v -> Error.raise_at l "text needs %s (a string) here, not %s" what (V.kind_name v))

(* §15.9: the character codes of a text's string: UTF-8 decoded with charset utf8 (characters
   beyond 0xFFFF dropped, as POV-Ray keeps UCS-2 only); with ascii, the default, a byte beyond 127
   becomes a space (before 3.5, it is kept) *)
let text_codes st loc s =
  let n = String.length s in
  let b i = Char.code s.[i] in
  match st.charset with
  | Sys ->
      (* POV-Ray 3.7 on Unix cannot convert the system's text format *)
      Error.raise_at loc "charset sys: the string cannot be converted from the system's text format to Unicode (use charset utf8)"
  | Utf8 ->
    let acc = ref [] and i = ref 0 in
    let cont k = !i + k < n && b (!i + k) land 0xC0 = 0x80 in
    while !i < n do
      let c = b !i in
      if c < 0x80 then (acc := c :: !acc; incr i)
      else if c land 0xE0 = 0xC0 && cont 1 then (acc := ((c land 0x1F) lsl 6) lor (b (!i + 1) land 0x3F) :: !acc; i := !i + 2)
      else if c land 0xF0 = 0xE0 && cont 1 && cont 2 then (
        acc := ((c land 0x0F) lsl 12) lor ((b (!i + 1) land 0x3F) lsl 6) lor (b (!i + 2) land 0x3F) :: !acc;
        i := !i + 3)
      else if c land 0xF8 = 0xF0 && cont 1 && cont 2 && cont 3 then i := !i + 4
      else begin
        warn st loc "the text string is not valid UTF-8: a byte 0x%02X is left out" c;
        incr i
      end
    done;
    Array.of_list (List.rev !acc)
  | Ascii ->
    let version = if st.version_set then st.version else 362 in
    let replaced = ref false in
    let codes = Array.init n (fun i -> let c = b i in if c > 127 && version >= 350 then (replaced := true; 32) else c) in
    if !replaced then warn st loc "a non-ASCII character of the text string has been replaced by a space (the charset is ascii; write global_settings { charset utf8 })";
    codes

(* §15.9: a font file is searched like an include file (the scene's directory, +L paths, the
   standard include directory), a name without an extension also with ".ttf" appended, and read
   through the access policy *)
let load_font st loc name =
  let found =
    match find_file ~inc:false st name with
    | Some p -> Some p
    | None -> if String.contains (Filename.basename name) '.' then None else find_file ~inc:false st (name ^ ".ttf")
  in
  match found with
  | None -> Error.raise_at loc "cannot find the font file \"%s\" (searched %s)" name (String.concat ", " (include_dirs st))
  | Some path -> (
      Access.check_read st.opts.access loc path;
      match Font.parse (read_file path) with
      | Ok f -> f
      | Error e -> Error.raise_at loc "the font file \"%s\" is not a usable TrueType font: %s" name e)

let show_vec (v : Vec.t) = Printf.sprintf "<%g, %g, %g>" v.x v.y v.z

(* A vector written as plain numbers, read without tokens (Lexer.scan_vector3) into [out]: true
   when that worked, and the parser then stands after the '>'. *)
let fast_vector3 st out =
  (* the '<' was read from the current frame, so the numbers are in the same text *)
  peek st == Lt && Lexer.scan_vector3 (top st).lx out && begin st.have <- false; true end

(* A vector of a mesh: by the fast path when it is written as plain numbers. *)
let mesh_vector st =
  let buf = [| 0.; 0.; 0. |] in
  if fast_vector3 st buf then Vec.make buf.(0) buf.(1) buf.(2) else parse_vector st

(* triangle { P1, P2, P3 } and smooth_triangle { P1, N1, P2, N2, P3, N3 } (§2.4, §2.5). *)
let parse_triangle_corners st ~smooth =
  let p1 = mesh_vector st in
  comma st;
  if smooth then begin
    let l1 = peek_loc st in
    let n1 = mesh_vector st in
    comma st;
    let p2 = mesh_vector st in
    comma st;
    let l2 = peek_loc st in
    let n2 = mesh_vector st in
    comma st;
    let p3 = mesh_vector st in
    comma st;
    let l3 = peek_loc st in
    let n3 = mesh_vector st in
    (p1, p2, p3, Some (unit_normal st l1 n1, unit_normal st l2 n2, unit_normal st l3 n3))
  end
  else begin
    let p2 = mesh_vector st in
    comma st;
    let p3 = mesh_vector st in
    (p1, p2, p3, None)
  end

(* Growable arrays for the lists of a mesh. With a capacity given (mesh2 announces its counts) the
   array is made once at that size and handed over as it is; otherwise the values go into chunks
   and [to_array] copies them once, so growing never holds more than the values and one copy. *)
module Grow = struct
  (* [chunks.(0)] has the first size (the capacity, or 1024), every later chunk [chunk] values *)
  type 'a t = { fill : 'a; mutable chunks : 'a array array; mutable n : int; mutable len : int }

  let chunk = 65536

  let create ?capacity x =
    let first = match capacity with Some c -> max 16 c | None -> 1024 in
    { fill = x; chunks = [| Array.make first x |]; n = 1; len = 0 }

  let first g = Array.length g.chunks.(0)

  let push g x =
    let f = first g in
    let c, i = if g.len < f then (0, g.len) else (1 + ((g.len - f) / chunk), (g.len - f) mod chunk) in
    if c = g.n then begin
      if g.n = Array.length g.chunks then g.chunks <- Array.append g.chunks (Array.make g.n [||]);
      g.chunks.(c) <- Array.make chunk g.fill;
      g.n <- g.n + 1
    end;
    Array.unsafe_set g.chunks.(c) i x;
    g.len <- g.len + 1

  let get g i =
    let f = first g in
    if i < f then g.chunks.(0).(i) else g.chunks.(1 + ((i - f) / chunk)).((i - f) mod chunk)

  let to_array g =
    if g.n = 1 && g.len = first g then g.chunks.(0)
    else begin
      let a = Array.make g.len g.fill in
      let at = ref 0 in
      for c = 0 to g.n - 1 do
        let k = min (Array.length g.chunks.(c)) (g.len - !at) in
        Array.blit g.chunks.(c) 0 a !at k;
        at := !at + k
      done;
      a
    end
end

(* Vertices (or normals) of a mesh { } merged when equal, as POV-Ray merges them: an open
   addressing table over the stored single-precision triples. *)
module Vertex_table = struct
  type t = { store : float Grow.t; mutable slots : int array; mutable count : int }

  let create () = { store = Grow.create 0.; slots = Array.make 1024 (-1); count = 0 }

  let hash x y z = Hashtbl.hash (Int64.bits_of_float x, Int64.bits_of_float y, Int64.bits_of_float z)

  let coord t i = Grow.get t.store i

  let rec insert t x y z =
    let mask = Array.length t.slots - 1 in
    let rec probe h =
      let k = t.slots.(h) in
      if k < 0 then begin
        t.slots.(h) <- t.count;
        Grow.push t.store x; Grow.push t.store y; Grow.push t.store z;
        t.count <- t.count + 1;
        t.count - 1
      end
      else if coord t (3 * k) = x && coord t ((3 * k) + 1) = y && coord t ((3 * k) + 2) = z then k
      else probe ((h + 1) land mask)
    in
    if 2 * (t.count + 1) > Array.length t.slots then begin
      let n = 2 * Array.length t.slots in
      let slots = Array.make n (-1) in
      for k = 0 to t.count - 1 do
        let rec place h = if slots.(h) < 0 then slots.(h) <- k else place ((h + 1) land (n - 1)) in
        place (hash (coord t (3 * k)) (coord t ((3 * k) + 1)) (coord t ((3 * k) + 2)) land (n - 1))
      done;
      t.slots <- slots;
      insert t x y z
    end
    else probe (hash x y z land mask)

  let to_array t = Grow.to_array t.store
end

(* A block "{ n, item, item … }" of a mesh2: [item] is called for each entry (with its location),
   and the number of entries must be n. *)
let parse_counted_block ?(start = fun (_ : int) -> ()) st what item =
  let loc = peek_loc st in
  open_block st what;
  let nloc = peek_loc st in
  let n = parse_float st in
  if n < 0. || Float.of_int (int_of_float n) <> n then Error.raise_at nloc "the count of %s must be a whole number, not %g" what n;
  let n = int_of_float n in
  (* room for the announced entries, within reason: a wrong count is reported after the block, and
     a count that lies must not take the memory (an entry takes at most 4 words: half the limit) *)
  start (min n (min 50_000_000 (st.opts.limits.memory_mb * 1048576 / 64)));
  let count = ref 0 in
  while peek st != RBrace do
    if peek st == Eof then close_block st what;
    comma st;
    if peek st != RBrace then begin
      item (peek_loc st);
      incr count
    end
  done;
  advance st;
  if !count <> n then Error.raise_at loc "%s says %d entries but lists %d" what n !count;
  n

let f32_vec (v : Vec.t) = Vec.make (f32 v.x) (f32 v.y) (f32 v.z)

let parse_texture_in_block st =
  (* texture { … } or a texture identifier inside a mesh triangle *)
  advance st;
  parse_texture st st.default_texture

(* Values povml cannot make yet; a declaration of one is kept as [V.Unsupported]. *)
let unsupported_rvalues =
  [ "material"; "normal"; "normal_map"; "texture_map"; "slope_map";
    "function"; "spline"; "media"; "density"; "fog"; "rainbow"; "sky_sphere"; "isosurface" ]

let unsupported_rvalue_set = set_of (unsupported_objects @ unsupported_rvalues)

let unsupported_object_set = set_of unsupported_objects

(* A light where an object may stand: a union of the light alone, dissolved into the scene's lights. *)
let light_union l = V.Csg { kind = Union; members = [ V.Member_light l ]; split = true }

let rec parse_object st : V.obj =
  let loc = peek_loc st in
  match peek st with
  | Ident ("triangle" | "smooth_triangle" as kw) ->
      advance st;
      open_block st kw;
      let smooth = kw = "smooth_triangle" in
      let p1, p2, p3, ns = parse_triangle_corners st ~smooth in
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
  | Ident "mesh" -> advance st; parse_mesh st loc
  | Ident "mesh2" -> advance st; parse_mesh2 st loc
  | Ident "sphere" ->
      advance st;
      open_block st "sphere";
      let centre = parse_vector st in
      ignore (accept st Comma) (* POV-Ray accepts the comma as optional *);
      let rloc = peek_loc st in
      let radius = parse_float st in
      if radius <= 0. then warn st rloc "sphere radius %g is not positive" radius;
      parse_object_mods st (new_obj (Sphere { centre; radius; trans = None }) loc) "sphere"
  | Ident "box" ->
      (* §15.1: the corners are sorted per axis; a flat or empty box is accepted silently *)
      advance st;
      open_block st "box";
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
      open_block st "cylinder";
      let p1 = parse_vector st in
      comma st;
      let p2 = parse_vector st in
      comma st;
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
      open_block st "cone";
      let p1 = parse_vector st in
      comma st;
      let r1 = parse_float st in
      comma st;
      let p2 = parse_vector st in
      comma st;
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
      open_block st "disc";
      let centre = parse_vector st in
      comma st;
      let nloc = peek_loc st in
      let normal = parse_vector st in
      comma st;
      let radius = parse_float st in
      comma st;
      let hole = if float_follows st then parse_float st else 0. in
      if Vec.length normal = 0. then Error.raise_at nloc "degenerate disc normal <0,0,0>";
      parse_object_mods st (new_obj (Canonical.disc ~centre ~normal ~radius ~hole) loc) "disc"
  | Ident "torus" ->
      (* §15.5: torus { R, r } (the comma optional), then its modifiers *)
      advance st;
      open_block st "torus";
      let major = parse_float st in
      ignore (accept st Comma);
      let minor = parse_float st in
      let shape = Scene.Torus { major; minor; sturm = false; trans = Transform.identity } in
      parse_object_mods st (new_obj shape loc) "torus"
  | Ident "text" ->
      (* §15.9: text { ttf "font" "string", thickness, <offset> }: a union of one extruded glyph
         per character (POV-Ray makes it a CSG union, dissolved like any union), then the
         modifiers, which move every letter *)
      advance st;
      open_block st "text";
      if not (accept_ident st "ttf") then
        (match peek st with
         | Ident "internal" -> Error.raise_at (peek_loc st) "internal fonts are not supported yet: name a TrueType font file with ttf \"file.ttf\""
         | _ -> unexpected st "'ttf' and a font file name");
      let floc = peek_loc st in
      let file = text_string st "the font file name" in
      ignore (accept st Comma);
      let sloc = peek_loc st in
      let str = text_string st "the string to render" in
      comma st;
      let depth = parse_float st in
      comma st;
      let offset = parse_vector st in
      let font = load_font st floc file in
      let letters =
        match Font.layout ~utf8:(st.charset = Utf8) font (text_codes st sloc str) ~offset with
        | Error e -> Error.raise_at floc "the font file \"%s\" cannot be read: %s" file e
        | Ok l -> l
      in
      if letters = [] then warn st sloc "the text string is empty: the text object has no letters";
      let members =
        List.map
          (fun ((outline : Glyph.outline), place) ->
            let trans = Transform.compose Transform.identity (Transform.translate place) in
            V.Member_obj (new_obj (Scene.Glyph { outline; depth; trans }) loc))
          letters
      in
      (* POV-Ray then turns the whole text by <0.001, 0.001, 0.001> degrees (to avoid cracks
         where an edge lies along an axis), before the modifiers *)
      let text = move_obj (Place.Rotate (Vec.make 0.001 0.001 0.001)) (new_obj_of (V.Csg { kind = Union; members; split = true }) loc) in
      parse_object_mods st text "text"
  | Ident "plane" ->
      advance st;
      open_block st "plane";
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
            | Some (V.Object o) -> advance st; { o with oloc = loc }
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
            let m = match parse_light_source st with Lone l -> V.Member_light l | Shaped o -> V.Member_obj o in
            members (m :: acc)
        | _ when object_follows st -> members (V.Member_obj (parse_object st) :: acc)
        | _ -> List.rev acc
      in
      let ms = nest st loc (fun () -> members []) in
      if List.length ms < 2 then warn st loc "a %s should have at least two members" kw;
      let ms =
        if kw <> "difference" then ms
        else List.mapi (fun i m -> match m with V.Member_obj o when i > 0 -> V.Member_obj (invert o) | V.Member_obj _ | V.Member_light _ -> m) ms
      in
      let kind : Scene.csg_kind = match kw with "union" -> Union | "merge" -> Merge | _ -> Intersection in
      parse_object_mods st (new_obj_of (V.Csg { kind; members = ms; split = kind = Union }) loc) kw
  | Ident "light_source" -> (
      match parse_light_source st with Lone l -> new_obj_of (light_union l) loc | Shaped o -> o)
  | Ident s -> (
      match cur_value st s with
      | Some (V.Object o) -> advance st; { o with oloc = loc }
      | Some (V.Light l) -> advance st; new_obj_of (light_union l) loc
      | Some (V.Unsupported u) -> unsupported_use loc s u.what u.at
      | _ -> unexpected st "an object")
  | _ -> unexpected st "an object"

(* A light_source, its looks_like object read by [parse_object] (§19.2). *)
and parse_light_source st = parse_light_with st ~object_:parse_object ~mods:parse_object_mods

(* The modifiers of an object, up to its closing brace. *)
and parse_object_mods st (o : V.obj) what : V.obj =
  let tex o = match o.V.texture with Some t -> t | None -> st.default_texture in
  let rec loop (o : V.obj) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; o
    | Ident "pigment" -> advance st; let t = tex o in loop { o with texture = Some { t with pigment = parse_pigment st t.pigment } }
    | Ident "finish" -> advance st; let t = tex o in loop { o with texture = Some { t with finish = parse_finish st t.finish } }
    | Ident "texture" ->
        advance st;
        if o.texture <> None then not_supported loc "layered textures (a texture added to an object that has one)";
        loop { o with texture = Some (parse_texture st st.default_texture) }
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
    | Ident "sturm" when is_torus o -> advance st; loop (set_sturm o)
    | Ident "hollow" -> advance st; ignore (parse_bool_opt st); loop o
    | Ident "inverse" -> advance st; loop (invert o)
    | Ident "split_union" -> (
        advance st;
        let on = parse_bool_opt st in
        (* §16.4: only a union is ever split; POV-Ray accepts the keyword on a merge (a kind of
           union to it) without effect and stops on any other object *)
        match o.shape with
        | Csg ({ kind = Union; _ } as c) -> loop { o with shape = Csg { c with split = on } }
        | Csg { kind = Merge; _ } | Csg { kind = Clipped; members = V.Member_obj { shape = Csg { kind = Union | Merge; _ }; _ } :: _; _ } ->
            loop o (* a merge, or a clipped union, is never split *)
        | Csg { kind = Intersection | Clipped; _ } | Prim _ -> Error.raise_at loc "split_union found in a non-union object")
    | Ident "clipped_by" ->
        (* §15.8: clipped_by { OBJECT … }: the object's hits are kept inside every clip object, and
           so is its Inside. The clip objects move with the object's later transforms; its
           texture, interior and flags stay on the clipped object. *)
        advance st;
        open_block st "clipped_by";
        let rec clips acc =
          match peek st with
          | Ident "bounded_by" -> not_supported (peek_loc st) "'clipped_by { bounded_by }'"
          | _ when object_follows st -> clips (V.Member_obj (parse_object st) :: acc)
          | _ -> List.rev acc
        in
        let cl = nest st loc (fun () -> clips []) in
        if cl = [] then unexpected st "an object in clipped_by";
        close_block st "clipped_by";
        let members =
          match o.shape with
          | Csg { kind = Clipped; members; _ } -> members @ cl
          | Csg { kind = Union | Merge | Intersection; _ } | Prim _ ->
              V.Member_obj { o with texture = None; interior = None; no_shadow = false } :: cl
        in
        loop { o with shape = Csg { kind = Clipped; members; split = false }; inverted = false }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s'" s)
    | _ -> unexpected st (Printf.sprintf "an object modifier or '}' closing '%s'" what)
  in
  loop o

(* Does an object (a keyword or an identifier of one) come next? *)
and object_follows st =
  match peek st with
  | Ident s when Names.mem object_set s -> true
  | Ident s -> ( match cur_value st s with Some (V.Object _ | V.Light _) -> true | Some (V.Unsupported _) -> true | _ -> Names.mem unsupported_object_set s)
  | _ -> false

(* mesh { triangle {…} smooth_triangle {…} … [inside_vector V] modifiers } (§2.6). Vertices are kept
   in single precision; each face is set up from the values as parsed. *)
and parse_mesh st loc =
  open_block st "mesh";
  let verts = Vertex_table.create () and norms = Vertex_table.create () and corners = Grow.create 0. in
  let fv = Grow.create 0 and fn = Grow.create 0 and ftex = Grow.create 0 in
  let textures = ref [] and ntex = ref 0 in
  let inside = ref None in
  let push3 g (v : Vec.t) = Grow.push g v.x; Grow.push g v.y; Grow.push g v.z in
  let add_vertex (v : Vec.t) = Grow.push fv (Vertex_table.insert verts (f32 v.x) (f32 v.y) (f32 v.z)) in
  let add_normal (n : Vec.t) = Grow.push fn (Vertex_table.insert norms (f32 n.x) (f32 n.y) (f32 n.z)) in
  let rec items () =
    match peek st with
    | Ident ("triangle" | "smooth_triangle" as kw) ->
        advance st;
        open_block st kw;
        let p1, p2, p3, ns = parse_triangle_corners st ~smooth:(kw = "smooth_triangle") in
        let tex =
          if is_ident st "texture" then begin
            (* POV-Ray takes only a texture identifier here: texture { T } *)
            advance st;
            open_block st "texture";
            let tl = peek_loc st in
            let t =
              match ident_of_kind st (function V.Texture t -> Some t | _ -> None) with
              | Some t -> t
              | None -> Error.raise_at tl "expected a texture identifier: a mesh triangle takes texture { Identifier }"
            in
            close_block st "texture";
            textures := t :: !textures;
            incr ntex;
            !ntex - 1
          end
          else -1
        in
        close_block st kw;
        add_vertex p1; add_vertex p2; add_vertex p3;
        push3 corners p1; push3 corners p2; push3 corners p3;
        (match ns with
        | Some (a, b, c) -> add_normal a; add_normal b; add_normal c
        | None -> Grow.push fn (-1); Grow.push fn (-1); Grow.push fn (-1));
        Grow.push ftex tex;
        items ()
    | Ident "inside_vector" -> advance st; inside := Some (parse_vector st); items ()
    | _ -> ()
  in
  items ();
  let mesh =
    Mesh.build ~vertices:(Vertex_table.to_array verts) ~vertex_normals:(Vertex_table.to_array norms) ~fv:(Grow.to_array fv)
      ~fn:(Grow.to_array fn) ~ftex:(Grow.to_array ftex) ~corners:(Some (Grow.to_array corners)) ~inside_vector:!inside
  in
  if mesh.faces = 0 then warn st loc "the mesh has no triangles with an area";
  let shape = Scene.Mesh { mesh; trans = None; textures = Array.of_list (List.rev !textures) } in
  parse_object_mods st (new_obj shape loc) "mesh"

(* mesh2 { vertex_vectors normal_vectors texture_list face_indices normal_indices inside_vector … } *)
and parse_mesh2 st loc =
  open_block st "mesh2";
  let vertices = ref None and normals = ref None and textures = ref [||] in
  let faces = ref None and nidx = ref None and inside = ref None in
  let vectors what ~unit =
    let g = ref (Grow.create 0.) in
    let n =
      parse_counted_block st what ~start:(fun n -> g := Grow.create ~capacity:(3 * n) 0.) (fun l ->
          let g = !g in
          let v = mesh_vector st in
          let v = f32_vec (if unit then unit_normal st l v else v) in
          Grow.push g v.x; Grow.push g v.y; Grow.push g v.z)
    in
    (n, Grow.to_array !g)
  in
  let indices st l limit what g =
    let v = mesh_vector st in
    let check x =
      if Float.of_int (int_of_float x) <> x || x < 0. || int_of_float x >= limit then
        Error.raise_at l "%s index %g is out of range: there are %d" what x limit;
      Grow.push g (int_of_float x)
    in
    check v.x; check v.y; check v.z
  in
  let rec sections () =
    let l = peek_loc st in
    match peek st with
    | Ident "vertex_vectors" -> advance st; vertices := Some (vectors "vertex_vectors" ~unit:false); sections ()
    | Ident "normal_vectors" -> advance st; normals := Some (vectors "normal_vectors" ~unit:true); sections ()
    | Ident "uv_vectors" -> not_supported l "'uv_vectors'"
    | Ident "texture_list" ->
        advance st;
        let g = ref [] in
        ignore
          (parse_counted_block st "texture_list" (fun l ->
               if is_ident st "texture" then g := parse_texture_in_block st :: !g
               else Error.raise_at l "expected a texture in texture_list"));
        textures := Array.of_list (List.rev !g);
        sections ()
    | Ident "face_indices" ->
        advance st;
        let nv = match !vertices with Some (n, _) -> n | None -> Error.raise_at l "face_indices before vertex_vectors" in
        let ntex = Array.length !textures in
        let fv = ref (Grow.create 0) and ftex = ref (Grow.create 0) in
        let n =
          parse_counted_block st "face_indices"
            ~start:(fun n ->
              fv := Grow.create ~capacity:(3 * n) 0;
              (* per-face texture indices only when there is a texture list *)
              if ntex > 0 then ftex := Grow.create ~capacity:n 0)
            (fun l ->
              let fv = !fv and ftex = !ftex in
              indices st l nv "vertex" fv;
              (* an optional texture index (three would interpolate, which is not read yet) *)
              let tex =
                let index_follows () = accept st Comma && (match peek st with Lt | RBrace -> false | _ -> true) in
                if index_follows () then begin
                  let tl = peek_loc st in
                  let t = parse_float st in
                  if index_follows () then not_supported tl "three texture indices per face (interpolated textures)";
                  if Float.of_int (int_of_float t) <> t || t < 0. || int_of_float t >= ntex then
                    Error.raise_at tl "texture index %g is out of range: the texture_list has %d" t ntex;
                  int_of_float t
                end
                else -1
              in
              if ntex > 0 then Grow.push ftex tex)
        in
        faces := Some (l, n, Grow.to_array !fv, if ntex > 0 then Grow.to_array !ftex else [||]);
        sections ()
    | Ident "normal_indices" ->
        advance st;
        let nn = match !normals with Some (n, _) -> n | None -> Error.raise_at l "normal_indices before normal_vectors" in
        let g = ref (Grow.create 0) in
        let n =
          parse_counted_block st "normal_indices" ~start:(fun n -> g := Grow.create ~capacity:(3 * n) 0) (fun l ->
              indices st l nn "normal" !g)
        in
        nidx := Some (l, n, Grow.to_array !g);
        sections ()
    | Ident "uv_indices" -> not_supported l "'uv_indices'"
    | Ident "inside_vector" -> advance st; inside := Some (parse_vector st); sections ()
    | _ -> ()
  in
  sections ();
  let nv, vs = match !vertices with Some v -> v | None -> Error.raise_at loc "mesh2 needs vertex_vectors" in
  let fl, nf, fv, ftex = match !faces with Some f -> f | None -> Error.raise_at loc "mesh2 needs face_indices" in
  let nn, ns = match !normals with Some n -> n | None -> (0, [||]) in
  (* §2.6: without normal_indices the face indices serve when there are as many normals as vertices;
     only the first faces, as many as there are normal indices, can be smooth *)
  let fn =
    match !nidx with
    | Some (nl, n, ni) ->
        if n > nf then Error.raise_at nl "normal_indices has %d entries but there are only %d faces" n nf;
        Array.init (3 * nf) (fun i -> if i < 3 * n then ni.(i) else -1)
    | None ->
        if nn = 0 then [||]
        else if nn = nv then fv
        else
          Error.raise_at fl "normal_vectors has %d entries and vertex_vectors %d: without normal_indices they must be as many" nn nv
  in
  let mesh = Mesh.build ~vertices:vs ~vertex_normals:ns ~fv ~fn ~ftex ~corners:None ~inside_vector:!inside in
  let shape = Scene.Mesh { mesh; trans = None; textures = !textures } in
  parse_object_mods st (new_obj shape loc) "mesh2"

(* §2.7: every object gets a texture and an interior; a legacy finish ior goes into the interior. *)
let resolved st (o : V.obj) =
  let texture = match o.texture with Some t -> t | None -> st.default_texture in
  let interior = match o.interior with Some i -> i | None -> Defaults.interior in
  let interior = match texture.finish.legacy_ior with Some ior -> { interior with ior } | None -> interior in
  let interior = if interior.ior = 0. then { interior with ior = 1. } else interior in
  (texture, interior)

(* The scene object of [o] with [shape], [texture], [interior] and [no_shadow]; its other flags and
   place are [o]'s. *)
let scene_obj (o : V.obj) ?(no_shadow = o.no_shadow) shape texture interior : Scene.obj =
  { Scene.shape; texture; interior; no_shadow; loc = o.oloc; no_image = o.no_image; no_reflection = o.no_reflection; double_illuminate = o.double_illuminate; looks_like = o.looks_like }

let finish_prim st (o : V.obj) shape : Scene.obj =
  let texture, interior = resolved st o in
  scene_obj o shape texture interior

(* A member's interior: its own, or its parent's shared (§16.5). *)
let member_interior (c : V.obj) parent =
  match c.interior with
  | Some i -> ((if i.ior = 0. then { i with Scene.ior = 1. } else i), true)
  | None -> (parent, false)

(* A CSG kept whole (§16.4, §16.5, §19.1): every member gets the parent's texture unless it has its
   own and shares the parent's interior unless it has its own; the parent's no_shadow goes to every
   member (only the top level's is ever tested); lights join the scene's lights. *)
let rec kept_obj st ~texture ~interior (o : V.obj) : Scene.obj =
  match o.shape with
  | Prim shape -> scene_obj o shape texture interior
  | Csg { kind; members; split = _ } ->
      let members =
        List.filter_map
          (function
            | V.Member_light l -> count_object st o.oloc; st.lights <- l :: st.lights; None
            | V.Member_obj c ->
                let texture = match c.texture with Some t -> t | None -> texture in
                let interior, own_interior = member_interior c interior in
                (* §16.5: the flags pass down to every member *)
                let c =
                  {
                    c with
                    no_shadow = c.no_shadow || o.no_shadow;
                    no_image = c.no_image || o.no_image;
                    no_reflection = c.no_reflection || o.no_reflection;
                  }
                in
                Some { Scene.mobj = kept_obj st ~texture ~interior c; inverted = c.inverted; own_interior })
          members
      in
      (* §16.4: a union whose members all have no_shadow has it too *)
      let no_shadow =
        o.no_shadow
        || (match kind with Union -> members <> [] && List.for_all (fun (m : Scene.member) -> m.mobj.no_shadow) members | Merge | Intersection | Clipped -> false)
      in
      scene_obj o ~no_shadow (Csg { kind; members }) texture interior

(* An object entering the scene (§16.4, §16.5): a union that may be split is dissolved, its members
   without a texture or interior take the union's, and its no_shadow goes to every member; its
   lights join the scene's. Another CSG enters whole. An inverted primitive enters as an
   intersection of itself alone, which has the same surface and the negated Inside (§16.3). *)
let rec add_object st (o : V.obj) =
  match o.shape with
  | Prim shape when not o.inverted ->
      count_object st o.oloc;
      st.objects <- finish_prim st o shape :: st.objects
  | Prim _ ->
      (* an inverted primitive: the intersection holds its texture and interior, so the camera's
         interior list and the hits name the same interior, as for POV-Ray's one object *)
      let m = V.Member_obj { o with texture = None; interior = None } in
      add_object st { o with shape = Csg { kind = Intersection; members = [ m ]; split = false }; inverted = false }
  | Csg { kind = Union; members = ms; split = true } ->
      List.iter
        (function
          | V.Member_light l -> count_object st o.oloc; st.lights <- l :: st.lights
          | V.Member_obj c ->
              add_object st
                {
                  c with
                  texture = (match c.texture with Some _ -> c.texture | None -> o.texture);
                  interior = (match c.interior with Some _ -> c.interior | None -> o.interior);
                  no_shadow = c.no_shadow || o.no_shadow;
                  no_image = c.no_image || o.no_image;
                  no_reflection = c.no_reflection || o.no_reflection;
                  looks_like = c.looks_like || o.looks_like;
                })
        ms
  | Csg { kind = Union | Merge | Intersection | Clipped; members = _; split = _ } ->
      count_object st o.oloc;
      let texture, interior = resolved st o in
      let obj = kept_obj st ~texture ~interior o in
      st.objects <- obj :: st.objects
