(* The plane: docs/povray-rules.md §2.3, §14.5 (a), POV-Ray's Plane. *)

type t = { nx : float; ny : float; nz : float; dist : float }
type moved = { pl : t; ptr : Transform.t; pnormal : Vec.t }

let epsilon = Precision.epsilon
let make (n : Vec.t) offset = { nx = n.x; ny = n.y; nz = n.z; dist = -.offset }
let moved normal offset ptr = { pl = make normal offset; ptr; pnormal = Transform.normalize (Transform.normal ptr normal) }

let depth (w : Scratch.t) p (o : Vec.t) (d : Vec.t) lo =
  let stats = w.stats in
  Stats.test stats Stats.plane;
  let ndd = (p.nx *. d.x) +. (p.ny *. d.y) +. (p.nz *. d.z) in
  if Float.abs ndd < epsilon then infinity
  else
    let ndo = (p.nx *. o.x) +. (p.ny *. o.y) +. (p.nz *. o.z) in
    let t = -.(ndo +. p.dist) /. ndd in
    if t >= w.lim.near && t <= w.lim.far && t >= lo then (Stats.hit stats Stats.plane; t)
    else infinity

let moved_depth (w : Scratch.t) { pl = p; ptr = t; _ } (o : Vec.t) (d : Vec.t) lo =
  let stats = w.stats and lim = w.lim in
  Stats.test stats Stats.plane;
  let vx = (d.x *. t.i00) +. (d.y *. t.i10) +. (d.z *. t.i20) in
  let vy = (d.x *. t.i01) +. (d.y *. t.i11) +. (d.z *. t.i21) in
  let vz = (d.x *. t.i02) +. (d.y *. t.i12) +. (d.z *. t.i22) in
  let ndd = (p.nx *. vx) +. (p.ny *. vy) +. (p.nz *. vz) in
  if Float.abs ndd < epsilon then infinity
  else
    let px = (o.x *. t.i00) +. (o.y *. t.i10) +. (o.z *. t.i20) +. t.i30 in
    let py = (o.x *. t.i01) +. (o.y *. t.i11) +. (o.z *. t.i21) +. t.i31 in
    let pz = (o.x *. t.i02) +. (o.y *. t.i12) +. (o.z *. t.i22) +. t.i32 in
    let ndo = (p.nx *. px) +. (p.ny *. py) +. (p.nz *. pz) in
    let t = -.(ndo +. p.dist) /. ndd in
    if t >= lim.near && t <= lim.far && t >= lo then (Stats.hit stats Stats.plane; t)
    else infinity

let inside pl (p : Vec.t) = (p.x *. pl.nx) +. (p.y *. pl.ny) +. (p.z *. pl.nz) +. pl.dist < epsilon

let moved_inside { pl; ptr; _ } p =
  let q = Transform.inv_point ptr p in
  (q.x *. pl.nx) +. (q.y *. pl.ny) +. (q.z *. pl.nz) +. pl.dist < epsilon

let magnitude p = Float.abs p.dist

let moved_magnitude { pl; ptr; _ } =
  let q = Transform.point ptr (Vec.make (-.pl.dist *. pl.nx) (-.pl.dist *. pl.ny) (-.pl.dist *. pl.nz)) in
  Array.fold_left (fun m x -> Float.max m (Float.abs x)) 0. [| q.x; q.y; q.z |]

let traits = { Traits.default with name = "plane"; costly = false; box_test_free = true; inverse_flag = false }
