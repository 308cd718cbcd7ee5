(* The sphere and the ellipsoid: docs/povray-rules.md §2.2, §14.5 (b), POV-Ray's Sphere. *)

type t = { cx : float; cy : float; cz : float; radius : float; r2 : float }
type uv_frame = { uv_trans : Transform.t; uv_centre : Vec.t }
type ellipsoid = { sp : t; etr : Transform.t; euv : uv_frame option }
type placed = { ps : t; puv : uv_frame }

let make (c : Vec.t) r = { cx = c.x; cy = c.y; cz = c.z; radius = r; r2 = r *. r }

(* Sphere::UVCoord's frame: the centre (mapped by [trans] when the sphere has one) brought back by
   the inverse of UV_Trans, once *)
let uv_frame ?trans uv_trans (c : Vec.t) =
  let c = match trans with Some t -> Transform.point t c | None -> c in
  { uv_trans; uv_centre = Transform.inv_point uv_trans c }

let ellipsoid sp etr uv_trans = { sp; etr; euv = Option.map (fun u -> uv_frame ~trans:etr u (Vec.make sp.cx sp.cy sp.cz)) uv_trans }
let placed ps uv_trans = { ps; puv = uv_frame uv_trans (Vec.make ps.cx ps.cy ps.cz) }

let[@inline] depth_at (stats : Stats.t) (lim : Limits.t) cx cy cz r2 (o : Vec.t) (d : Vec.t) lo =
  Stats.test stats Stats.sphere;
  let ocx = cx -. o.x and ocy = cy -. o.y and ocz = cz -. o.z in
  let ocs = (ocx *. ocx) +. (ocy *. ocy) +. (ocz *. ocz) in
  let tca = (ocx *. d.x) +. (ocy *. d.y) +. (ocz *. d.z) in
  if ocs >= r2 && tca < lim.tangent then infinity
  else
    let h2 = r2 -. ocs +. (tca *. tca) in
    if h2 <= lim.tangent then infinity
    else begin
      let h = sqrt h2 in
      let t1 = tca -. h in
      if t1 > lim.near && t1 < lim.far && t1 >= lo then (Stats.hit stats Stats.sphere; t1)
      else
        let t2 = tca +. h in
        if t2 > lim.near && t2 < lim.far && t2 >= lo then (Stats.hit stats Stats.sphere; t2)
        else infinity
    end

let depth (w : Scratch.t) s o d lo = depth_at w.stats w.lim s.cx s.cy s.cz s.r2 o d lo

(* Everything stays in unboxed floats. *)
let ellipsoid_depth (w : Scratch.t) { sp = s; etr = t; _ } (o : Vec.t) (d : Vec.t) lo =
  let stats = w.stats and lim = w.lim in
  Stats.test stats Stats.sphere;
  let px = (o.x *. t.i00) +. (o.y *. t.i10) +. (o.z *. t.i20) +. t.i30 in
  let py = (o.x *. t.i01) +. (o.y *. t.i11) +. (o.z *. t.i21) +. t.i31 in
  let pz = (o.x *. t.i02) +. (o.y *. t.i12) +. (o.z *. t.i22) +. t.i32 in
  let vx = (d.x *. t.i00) +. (d.y *. t.i10) +. (d.z *. t.i20) in
  let vy = (d.x *. t.i01) +. (d.y *. t.i11) +. (d.z *. t.i21) in
  let vz = (d.x *. t.i02) +. (d.y *. t.i12) +. (d.z *. t.i22) in
  let len = sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
  (* VInverseScaleEq: times the reciprocal *)
  let k = 1. /. len in
  let vx = vx *. k and vy = vy *. k and vz = vz *. k in
  let ocx = s.cx -. px and ocy = s.cy -. py and ocz = s.cz -. pz in
  let ocs = (ocx *. ocx) +. (ocy *. ocy) +. (ocz *. ocz) in
  let tca = (ocx *. vx) +. (ocy *. vy) +. (ocz *. vz) in
  if ocs >= s.r2 && tca < lim.tangent then infinity
  else
    let h2 = s.r2 -. ocs +. (tca *. tca) in
    if h2 <= lim.tangent then infinity
    else begin
      let h = sqrt h2 in
      let t1 = tca -. h in
      if t1 > lim.near && t1 < lim.far && t1 /. len >= lo then (Stats.hit stats Stats.sphere; t1 /. len)
      else
        let t2 = tca +. h in
        if t2 > lim.near && t2 < lim.far && t2 /. len >= lo then (Stats.hit stats Stats.sphere; t2 /. len)
        else infinity
    end

let hits (w : Scratch.t) s id (o : Vec.t) (d : Vec.t) lo n =
  let stats = w.stats and lim = w.lim in
  Stats.test stats Stats.sphere;
  let ocx = s.cx -. o.x and ocy = s.cy -. o.y and ocz = s.cz -. o.z in
  let ocs = (ocx *. ocx) +. (ocy *. ocy) +. (ocz *. ocz) in
  let tca = (ocx *. d.x) +. (ocy *. d.y) +. (ocz *. d.z) in
  if ocs >= s.r2 && tca < lim.tangent then n
  else
    let h2 = s.r2 -. ocs +. (tca *. tca) in
    if h2 <= lim.tangent then n
    else
      let h = sqrt h2 in
      let t1 = tca -. h and t2 = tca +. h in
      let n0 = n in
      let n = if t1 > lim.near && t1 < lim.far then Scratch.push_ray w n lo t1 (-1) id o d else n in
      let n = if t2 > lim.near && t2 < lim.far then Scratch.push_ray w n lo t2 (-1) id o d else n in
      if n > n0 then Stats.hit stats Stats.sphere;
      n

let ellipsoid_hits (w : Scratch.t) { sp = s; etr = t; _ } id (o : Vec.t) (d : Vec.t) lo n =
  let stats = w.stats and lim = w.lim in
  Stats.test stats Stats.sphere;
  let q = Transform.inv_point t o and v = Transform.inv_direction t d in
  let len = Vec.length v in
  let k = 1. /. len in
  let v = Vec.scale k v in
  let ocx = s.cx -. q.x and ocy = s.cy -. q.y and ocz = s.cz -. q.z in
  let ocs = (ocx *. ocx) +. (ocy *. ocy) +. (ocz *. ocz) in
  let tca = (ocx *. v.x) +. (ocy *. v.y) +. (ocz *. v.z) in
  if ocs >= s.r2 && tca < lim.tangent then n
  else
    let h2 = s.r2 -. ocs +. (tca *. tca) in
    if h2 <= lim.tangent then n
    else
      let h = sqrt h2 in
      let root n t0 =
        if t0 > lim.near && t0 < lim.far && t0 /. len >= lo then
          let p = Transform.point t (Vec.madd q t0 v) in
          Scratch.push_hit w n (t0 /. len) (-1) id p.x p.y p.z
        else n
      in
      let n0 = n in
      let n = root (root n (tca -. h)) (tca +. h) in
      if n > n0 then Stats.hit stats Stats.sphere;
      n

(* Sphere::Normal: VInverseScaleEq, times the reciprocal of the radius (a division can differ in
   the last bit, which a normal pattern's cell boundary turns into a visible difference) *)
let normal s (p : Vec.t) =
  let k = 1. /. s.radius in
  Vec.make ((p.x -. s.cx) *. k) ((p.y -. s.cy) *. k) ((p.z -. s.cz) *. k)

let ellipsoid_normal { sp = s; etr; _ } p =
  let q = Transform.inv_point etr p in
  Transform.normalize (Transform.normal etr (Vec.make (q.x -. s.cx) (q.y -. s.cy) (q.z -. s.cz)))

let inside s (p : Vec.t) =
  let dx = p.x -. s.cx and dy = p.y -. s.cy and dz = p.z -. s.cz in
  (dx *. dx) +. (dy *. dy) +. (dz *. dz) < s.r2

let ellipsoid_inside { sp = s; etr; _ } p =
  let q = Transform.inv_point etr p in
  let dx = s.cx -. q.x and dy = s.cy -. q.y and dz = s.cz -. q.z in
  (dx *. dx) +. (dy *. dy) +. (dz *. dz) < s.r2

let bounds s =
  let r = Float.abs s.radius in
  [| s.cx -. r; s.cy -. r; s.cz -. r; s.cx +. r; s.cy +. r; s.cz +. r |]

let ellipsoid_bounds { sp = s; etr; _ } =
  let r = Float.abs s.radius in
  Transform.bounds etr [| s.cx -. r; s.cy -. r; s.cz -. r; s.cx +. r; s.cy +. r; s.cz +. r |]

let pov_box s =
  let f32 = Precision.f32 and r = s.radius in
  [| f32 (s.cx -. r); f32 (s.cy -. r); f32 (s.cz -. r); f32 (2. *. r); f32 (2. *. r); f32 (2. *. r) |]

let ellipsoid_pov_box { sp; etr; _ } = Pov_box.mapped etr (pov_box sp)

let onto cx cy cz r (q : Vec.t) =
  let dx = q.x -. cx and dy = q.y -. cy and dz = q.z -. cz in
  let len = sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
  if len = 0. then q else let k = Float.abs r /. len in Vec.make (cx +. (k *. dx)) (cy +. (k *. dy)) (cz +. (k *. dz))

let refine s p = onto s.cx s.cy s.cz s.radius p
let ellipsoid_refine { sp = s; etr; _ } p = Transform.point etr (onto s.cx s.cy s.cz s.radius (Transform.inv_point etr p))

(* Sphere::UVCoord from the point and the centre in the UV frame: u the angle about the y axis from
   +x (towards +z), v the angle from the xz plane, each scaled to [0, 1]. The direction is divided
   by its length (not times the reciprocal); a pole has u = 0. At the centre POV-Ray leaves its
   result unset; this gives (0, 0). *)
let uv_of (q : Vec.t) (c : Vec.t) =
  let x = q.x -. c.x and y = q.y -. c.y and z = q.z -. c.z in
  let len = sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
  if len = 0.0 then Vec.zero
  else
    let x = x /. len and y = y /. len and z = z /. len in
    let phi = 0.5 +. (asin y /. Float.pi) in
    let len = (x *. x) +. (z *. z) in
    let theta =
      if len > Precision.epsilon then
        let len = sqrt len in
        let theta =
          if z = 0.0 then if x > 0. then 0.0 else Float.pi
          else
            let theta = acos (x /. len) in
            if z < 0.0 then (2. *. Float.pi) -. theta else theta
        in
        theta /. (2. *. Float.pi)
      else 0.
    in
    Vec.make theta phi 0.

let uv s p = uv_of p (Vec.make s.cx s.cy s.cz)
let placed_uv { puv; _ } p = uv_of (Transform.inv_point puv.uv_trans p) puv.uv_centre

let ellipsoid_uv { sp; euv; _ } p =
  match euv with
  | Some f -> uv_of (Transform.inv_point f.uv_trans p) f.uv_centre
  | None -> uv_of p (Vec.make sp.cx sp.cy sp.cz)

let traits = { Traits.default with name = "sphere"; costly = false; box_test_free = true }
let ellipsoid_traits = { traits with costly = true }
