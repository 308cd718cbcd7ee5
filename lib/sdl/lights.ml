(* The light_source block (docs/povray-rules.md §10.2, §18.2, §18.3, §19.2). *)

open Token
open Reader
open Expr
open Object_value

(* A light source as read: a light alone, or a light with its looks_like object, which is kept
   as a union of the two so that later transforms move both and the scene dissolves it (§19.2). *)
type light_source = Lone of Scene.light | Shaped of V.obj

(* light_source { centre, colour … } (§10.2, §18.2, §18.3, §19.2). radius, falloff and tightness
   need a spotlight or cylinder keyword written before them, point_at one of those or parallel;
   [object_] reads the object of a looks_like, [mods] its modifiers. *)
let parse st ~object_ ~mods =
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
            Shaped (new_csg Union [ V.Member_light l; V.Member_obj o ] ~split:true lloc))
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
