(* Vector functions of splines, pigments and transforms. *)

open Reader

let terms_value t = if Array.length t = 5 then Value.Colour t else Value.Vector t

let spline s floc =
  let n = Spline.terms s in
  let veval fr = Array.sub (Spline.eval s fr.(0)) 0 n in
  let eval fr = (veval fr).(0) in
  { Fn.name = ""; params = [| "t" |]; frame = 1; size = n; eval; veval; counted = Lazy.from_val eval; floc }

let spline_value s t = terms_value (Array.sub (Spline.eval s t) 0 (Spline.terms s))

(* S(t) and S(t, kind) of a declared spline (Parse_Spline_Call) *)
let spline_call st sp ~parse_float =
  advance st;
  expect st LParen "'(' and the time after a spline identifier";
  let t = parse_float st in
  let sp =
    if accept st Comma then
      let kloc = peek_loc st in
      match peek st with
      | Ident "linear_spline" -> advance st; Spline.with_kind sp Spline.Linear
      | Ident "quadratic_spline" -> advance st; Spline.with_kind sp Spline.Quadratic
      | Ident "cubic_spline" -> advance st; Spline.with_kind sp Spline.Cubic
      | Ident "natural_spline" -> advance st; Spline.with_kind sp Spline.Natural
      | _ -> Error.raise_at kloc "expected linear_spline, quadratic_spline, natural_spline, or cubic_spline"
    else sp
  in
  expect st RParen "')' after the spline's time";
  spline_value sp t


let vector_fn ~size ~veval floc =
  let eval fr = (veval fr).(0) in
  { Fn.name = ""; params = [| "x"; "y"; "z" |]; frame = 3; size; eval; veval; counted = Lazy.from_val eval; floc }

let point fr = Vec.make fr.(0) fr.(1) fr.(2)

let pigment st p floc =
  let f = Precision.f32 in
  let veval fr =
    let c = Pigment.colour_at st.noise_generator p Patterns.no_hit (point fr) in
    [| f c.red; f c.green; f c.blue; f c.filter; f c.transmit |]
  in
  vector_fn ~size:5 ~veval floc

let transform t floc =
  let veval fr = let q = Transform.point t (point fr) in [| q.x; q.y; q.z |] in
  vector_fn ~size:3 ~veval floc


let special st ~parse_transform kw loc =
  match kw with
  | "pigment" -> advance st; Some (pigment st (st.read_pigment st) loc)
  | "transform" -> advance st; Some (transform (parse_transform st) loc)
  | _ -> None
