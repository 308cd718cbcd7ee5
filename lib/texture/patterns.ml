(* The value of every pattern (pattern.cpp); §17.4–§17.7 for the first four. *)

type hit = { normal : Vec.t; dir : Vec.t }

let no_hit = { normal = Vec.make 0. 1. 0.; dir = Vec.make 0. 0. 1. }

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


let value (p : Scene.pattern) (_warps : Scene.warp list) (_gen : int) (_hit : hit) q =
  match p with
  | Checker -> checker q
  | Gradient v -> gradient v q
  | Hexagon -> hexagon q
  | Brick { size; mortar } -> brick size mortar q
  | _ -> failwith "Patterns.value: not written yet"
