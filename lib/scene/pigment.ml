(* Pigment patterns and colour maps, after POVRAY-3.7 §17. *)

(* C's (int) cast of a double, as the checker's sum of floors is converted *)
let c_int x = if Float.is_nan x || Float.abs x >= 2147483648. then min_int else int_of_float x

(* §17.4: a coordinate that is an integer, or within 1e-10 below one, belongs to the cell above *)
let checker (q : Vec.t) =
  let s = Precision.(floor (q.x +. epsilon) +. floor (q.y +. epsilon) +. floor (q.z +. epsilon)) in
  if c_int s land 1 = 1 then 1. else 0.

(* §17.5: values up to 1 (negatives included) pass unchanged; the wrap of §17.1 does the rest *)
let gradient (v : Vec.t) (q : Vec.t) =
  let r = (q.x *. v.x) +. (q.y *. v.y) +. (q.z *. v.z) in
  if r > 1. then Float.rem r 1. else r

(* §17.6: the cell of a hexagonal tiling of the XZ plane, in a 6×6 grid of half-unit columns and
   rows of √3/2 *)
let hexagon (q : Vec.t) =
  let x = Float.abs q.x in
  let z = if q.z < 0. then 5.196152424 -. Float.abs q.z else q.z in
  let xs = x /. 0.5 and zs = z /. 0.866025404 in
  let xs = xs -. (6. *. floor (xs /. 6.)) and zs = zs -. (6. *. floor (zs /. 6.)) in
  let xm = int_of_float (floor xs) mod 6 and zm = int_of_float (floor zs) mod 6 in
  match xm with
  | 0 | 5 -> ( match zm with 0 | 5 -> 0. | 1 | 2 -> 1. | _ -> 2.)
  | 2 | 3 -> ( match zm with 0 | 1 -> 2. | 2 | 3 -> 0. | _ -> 1.)
  | _ ->
      let xl = xs -. float_of_int xm and zl = zs -. float_of_int zm in
      let xl = if (xm + zm) land 1 = 1 then 1. -. xl else xl in
      let xl = if xl = 0. then 0.0001 else xl in
      if zl /. xl < 1. then (match zm with 0 | 3 -> 0. | 2 | 5 -> 1. | _ -> 2.)
      else match zm with 0 | 3 -> 2. | 2 | 5 -> 0. | _ -> 1.

(* §17.7: the fractional part, taken into [0, 1) for negative values *)
let frac a =
  let f = a -. Float.trunc a in
  if f < 0. then f +. 1. else f

let brick (size : Vec.t) mortar (q : Vec.t) =
  let m = mortar +. Precision.epsilon in
  let x = q.x +. m and y = q.y +. m and z = q.z +. m in
  let w = size.x and h = size.y and d = size.z in
  if frac (y /. h) <= mortar /. h then 0.
  else
    let odd = frac (y /. (2. *. h)) > 0.5 in
    if (not odd) && frac (x /. w) <= mortar /. w then 0.
    else if odd && frac ((x /. w) +. 0.5) <= mortar /. w then 0.
    else if odd && frac (z /. d) <= mortar /. d then 0.
    else if (not odd) && frac ((z /. d) +. 0.5) <= mortar /. d then 0.
    else 1.

let pattern_value (p : Scene.pattern) q =
  match p with
  | Checker -> checker q
  | Gradient v -> gradient v q
  | Hexagon -> hexagon q
  | Brick { size; mortar } -> brick size mortar q

let two_pi = 2. *. Float.pi

(* sin(2π·frac v) as POV-Ray computes it, the fraction scaled by 50000 and back first (v ≥ 0 here,
   after the wrap of §17.1) *)
let cycloidal v = sin (((v -. floor v) *. 50000.) /. 50000. *. two_pi)

let shape_value ~frequency ~phase (w : Scene.wave) v =
  (* §17.1: C fmod with the modulus 1.00001, not 1 *)
  let v = if frequency <> 0. then Float.rem ((v *. frequency) +. phase) 1.00001 else v in
  let v = if v < 0. then v -. floor v else v in
  match w with
  | Ramp -> v
  | Triangle_wave ->
      let f = v -. floor v in
      if f < 0.5 then 2. *. f else 2. *. (1. -. f)
  | Sine_wave -> (1. +. cycloidal v) *. 0.5
  | Scallop_wave -> Float.abs (cycloidal (v *. 0.5))
  | Cubic_wave -> v *. v *. (3. -. (2. *. v))
  | Poly_wave e -> Float.pow v e

(* §17.2: entries are searched in the order written; colour channels are single precision *)
let lookup (map : Scene.map_entry array) v =
  let n = Array.length map in
  let last = map.(n - 1) in
  if v >= last.value then last.colour
  else
    let rec search (prev : Scene.map_entry) i =
      let cur = map.(i) in
      if v > cur.value then search cur (i + 1) else (prev, cur)
    in
    let prev, cur = search map.(0) 0 in
    if v = cur.value || prev == cur then cur.colour
    else
      let f = (v -. prev.value) /. (cur.value -. prev.value) in
      let mix a b = Precision.(f32 (a +. f32 (f *. f32 (b -. a)))) in
      let p = prev.colour and c = cur.colour in
      {
        Colour.red = mix p.red c.red;
        green = mix p.green c.green;
        blue = mix p.blue c.blue;
        filter = mix p.filter c.filter;
        transmit = mix p.transmit c.transmit;
      }

let f32_colour (c : Colour.t) =
  Precision.{ Colour.red = f32 c.red; green = f32 c.green; blue = f32 c.blue; filter = f32 c.filter; transmit = f32 c.transmit }

(* §17.2 for a pigment map: the same search; the entries' pigments are evaluated at the point the
   outer pattern saw, each through its own transform, and their colours blended *)
let rec at_pattern_point (p : Scene.patterned) q =
  let v = shape_value ~frequency:p.frequency ~phase:p.phase p.wave (pattern_value p.pattern q) in
  if Array.length p.pigments = 0 then lookup p.map v
  else
    let map = p.pigments in
    let n = Array.length map in
    let last = map.(n - 1) in
    if v >= last.pvalue then inner last.pigment q
    else
      let rec search (prev : Scene.pigment_entry) i =
        let cur = map.(i) in
        if v > cur.pvalue then search cur (i + 1) else (prev, cur)
      in
      let prev, cur = search map.(0) 0 in
      if v = cur.pvalue || prev == cur then inner cur.pigment q
      else
        let f = (v -. prev.pvalue) /. (cur.pvalue -. prev.pvalue) in
        let mix a b = Precision.(f32 (a +. f32 (f *. f32 (b -. a)))) in
        let c = inner cur.pigment q and p = inner prev.pigment q in
        {
          Colour.red = mix p.red c.red;
          green = mix p.green c.green;
          blue = mix p.blue c.blue;
          filter = mix p.filter c.filter;
          transmit = mix p.transmit c.transmit;
        }

and inner (pg : Scene.pigment) q =
  match pg with
  | Solid c | Solid_placed { colour = c; _ } -> f32_colour c
  | Pattern p -> at_pattern_point p (match p.ptrans with None -> q | Some t -> Transform.inv_point t q)

let eval (p : Scene.patterned) (x : Vec.t) = at_pattern_point p (match p.ptrans with None -> x | Some t -> Transform.inv_point t x)

let colour_at (p : Scene.pigment) x = match p with Solid c | Solid_placed { colour = c; _ } -> c | Pattern pp -> eval pp x

let clear (c : Colour.t) = Float.abs c.filter <= Precision.epsilon && Float.abs c.transmit <= Precision.epsilon

let rec opaque (p : Scene.pigment) =
  match p with
  | Solid c | Solid_placed { colour = c; _ } -> clear c
  | Pattern pp ->
      if Array.length pp.pigments = 0 then Array.for_all (fun (e : Scene.map_entry) -> clear e.colour) pp.map
      else Array.for_all (fun (e : Scene.pigment_entry) -> opaque e.pigment) pp.pigments

let f32_entry v (c : Colour.t) : Scene.map_entry =
  {
    value = Precision.f32 v;
    colour = f32_colour c;
  }

let rgb r g b = { Colour.black with red = r; green = g; blue = b }

let default_map (p : Scene.pattern) =
  match p with
  | Checker -> [| f32_entry 0. (rgb 0. 0. 1.); f32_entry 1. (rgb 0. 1. 0.) |]
  | Hexagon -> [| f32_entry 0. (rgb 0. 0. 1.); f32_entry 1. (rgb 0. 1. 0.); f32_entry 2. (rgb 1. 0. 0.) |]
  | Brick _ -> [| f32_entry 0. (rgb 0.5 0.5 0.5); f32_entry 1. (rgb 0.6 0.15 0.15) |]
  | Gradient _ -> [| f32_entry 0. (rgb 0. 0. 0.); f32_entry 1. (rgb 1. 1. 1.) |]

let transform (p : Scene.pigment) t : Scene.pigment =
  (* Transform_Tpattern: composed into the head transform, created on the identity first; a plain
     colour keeps its transform too, for an edit that gives it a pattern (§17.9) *)
  match p with
  | Solid colour -> Solid_placed { colour; strans = Transform.compose Transform.identity t }
  | Solid_placed { colour; strans } -> Solid_placed { colour; strans = Transform.compose strans t }
  | Pattern pp ->
      let base = match pp.ptrans with None -> Transform.identity | Some m -> m in
      Pattern { pp with ptrans = Some (Transform.compose base t) }
