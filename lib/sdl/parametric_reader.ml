(* The reader of parametric { … } (POV-Ray's Parse_Parametric). *)

open Token
open Reader

type precompute = { depth : float; x : bool; y : bool; z : bool; at : Loc.t }

(* Parse_Function after [function], else Parse_FunctionContent: a bare expression of x y z (u v),
   which starts after the token POV-Ray's EXPECT took to see that it is not [function] *)
let func st =
  match peek st with
  | Ident "function" ->
      advance st;
      Fn_reader.anonymous st
  | _ ->
      advance st;
      let loc = peek_loc st in
      let e = Fn_reader.body st ~name:"" in
      Fn_compile.compile ~name:"" ~params:[| "x"; "y"; "z" |] ~loc ~warn:(fun l m -> warn st l "%s" m) e

(* contained_by { box { A, B } } (the corners sorted per axis) or { sphere { C, R } }; anything
   else leaves the container as it was *)
let container st current =
  match Container_reader.read st with
  | Some (Box (a, b)) ->
      Parametric.Box_container (Box.make (Vec.make (Float.min a.x b.x) (Float.min a.y b.y) (Float.min a.z b.z)) (Vec.make (Float.max a.x b.x) (Float.max a.y b.y) (Float.max a.z b.z)))
  | Some (Sphere (centre, radius)) -> Parametric.Sphere_container { centre; radius }
  | None -> current

(* precompute DEPTH [,] [x] [,] [y] [,] [z]: the axes in that order, each optional *)
let precompute st (prev : precompute option) =
  let at = peek_loc st in
  let depth = Expr.c_int (Expr.parse_float st) in
  let axis name =
    skip_comma st;
    accept_ident st name
  in
  let x = axis "x" in
  let y = axis "y" in
  let z = axis "z" in
  match prev with
  | None -> { depth; x; y; z; at }
  | Some p -> { depth; x = p.x || x; y = p.y || y; z = p.z || z; at }

let parametric st =
  let fx = func st in
  skip_comma st;
  let fy = func st in
  skip_comma st;
  let fz = func st in
  let c1 = Spline_reader.uv_vector st in
  skip_comma st;
  let c2 = Spline_reader.uv_vector st in
  let accuracy = ref 0.001 and max_gradient = ref 1. and pre = ref None in
  let box = Parametric.Box_container (Box.make (Vec.make (-1.) (-1.) (-1.)) (Vec.make 1. 1. 1.)) in
  let cont = ref box in
  let rec items () =
    match peek st with
    | Ident "accuracy" ->
        advance st;
        let loc = peek_loc st in
        let a = Expr.parse_float st in
        if not (a > 0.) then Error.raise_at loc "parametric accuracy must be positive (%g given)" a;
        accuracy := a;
        items ()
    | Ident "max_gradient" ->
        advance st;
        max_gradient := Expr.parse_float st;
        items ()
    | Ident "precompute" ->
        advance st;
        pre := Some (precompute st !pre);
        items ()
    | Ident "contained_by" ->
        advance st;
        cont := container st !cont;
        items ()
    | _ -> ()
  in
  items ();
  let s = Parametric.make (fx, fy, fz) c1 c2 ~accuracy:!accuracy ~max_gradient:!max_gradient !cont in
  (Scene.Parametric s, !pre)

let rec finish pre (o : V.obj) : V.obj =
  match (pre, o.shape) with
  | Some p, Prim (Parametric s) when p.x || p.y || p.z ->
      if p.depth < 1. || p.depth > 20. then Error.raise_at p.at "Precompute: invalid depth";
      { o with shape = Prim (Parametric (Parametric.precompute s ~depth:(int_of_float p.depth) ~x:p.x ~y:p.y ~z:p.z)) }
  | Some _, Csg { kind = Clipped; members = V.Member_obj c :: clips; split; box } ->
      { o with shape = Csg { kind = Clipped; members = V.Member_obj (finish pre c) :: clips; split; box } }
  | (Some _ | None), (Prim _ | Csg _) -> o
