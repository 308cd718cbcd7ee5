(* contained_by { … } of isosurfaces and parametric surfaces. *)

open Reader

type t = Box of Vec.t * Vec.t | Sphere of Vec.t * float

let read st =
  open_block st "contained_by";
  let c =
    match peek st with
    | Ident "box" ->
        advance st;
        open_block st "box";
        let a = Expr.parse_vector st in
        skip_comma st;
        let b = Expr.parse_vector st in
        close_block st "box";
        Some (Box (a, b))
    | Ident "sphere" ->
        advance st;
        open_block st "sphere";
        let centre = Expr.parse_vector st in
        skip_comma st;
        let radius = Expr.parse_float st in
        close_block st "sphere";
        Some (Sphere (centre, radius))
    | _ -> None
  in
  close_block st "contained_by";
  c
