(* The cylinder and the cone: docs/povray-rules.md §15.2, §15.3, §14.5 (b), POV-Ray's Cone. *)

type t = { ctr : Transform.t; dist : float; cyl : bool; closed : bool }

let epsilon = Precision.epsilon

(* §15.2, §15.3: cylinders and cones reject canonical depths up to Cone_Tolerance (1e-9) *)
let cone_tolerance = 1e-9
let base_hit = 1
let cap_hit = 2
let side_hit = 3

let[@inline] put (out : float array) n depth part =
  out.(2 * n) <- depth;
  out.((2 * n) + 1) <- part;
  n + 1

(* The ray is brought into canonical space with its direction renormalised. Nothing is allocated. *)
let crossings (w : Scratch.t) (c : t) (o : Vec.t) (d : Vec.t) (out : float array) =
  let stats = w.stats in
  Stats.test stats Stats.cone;
  let t = c.ctr in
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
  let near = if w.robust then 0. else cone_tolerance and far = w.lim.far in
  let side = float_of_int side_hit in
  let n =
    if c.cyl then begin
      let a = (vx *. vx) +. (vy *. vy) in
      if a > epsilon then begin
        let b = (px *. vx) +. (py *. vy) in
        let cc = (px *. px) +. (py *. py) -. 1.0 in
        let dsc = (b *. b) -. (a *. cc) in
        if dsc >= 0.0 then begin
          let sq = sqrt dsc in
          (* the far root first, as Cone::Intersect lists them *)
          let t1 = (-.b +. sq) /. a and t2 = (-.b -. sq) /. a in
          let z1 = pz +. (t1 *. vz) and z2 = pz +. (t2 *. vz) in
          let n = if t1 > near && t1 < far && z1 >= 0.0 && z1 <= 1.0 then put out 0 (t1 /. len) side else 0 in
          if t2 > near && t2 < far && z2 >= 0.0 && z2 <= 1.0 then put out n (t2 /. len) side else n
        end
        else 0
      end
      else 0
    end
    else begin
      let a = (vx *. vx) +. (vy *. vy) -. (vz *. vz) in
      let b = (vx *. px) +. (vy *. py) -. (vz *. pz) in
      let cc = (px *. px) +. (py *. py) -. (pz *. pz) in
      if Float.abs a < epsilon then begin
        (* the ray parallel to a generator: one crossing *)
        if Float.abs b > epsilon then begin
          let t1 = -0.5 *. cc /. b in
          let z1 = pz +. (t1 *. vz) in
          if t1 > near && t1 < far && z1 >= c.dist && z1 <= 1.0 then put out 0 (t1 /. len) side else 0
        end
        else 0
      end
      else begin
        let dsc = (b *. b) -. (a *. cc) in
        if dsc >= 0.0 then begin
          let sq = sqrt dsc in
          let t1 = (-.b -. sq) /. a and t2 = (-.b +. sq) /. a in
          let z1 = pz +. (t1 *. vz) and z2 = pz +. (t2 *. vz) in
          let n = if t1 > near && t1 < far && z1 >= c.dist && z1 <= 1.0 then put out 0 (t1 /. len) side else 0 in
          if t2 > near && t2 < far && z2 >= c.dist && z2 <= 1.0 then put out n (t2 /. len) side else n
        end
        else 0
      end
    end
  in
  let n =
    if c.closed && Float.abs vz > epsilon then begin
      let s1 = (1.0 -. pz) /. vz in
      let a1 = px +. (s1 *. vx) and b1 = py +. (s1 *. vy) in
      let n = if (a1 *. a1) +. (b1 *. b1) <= 1.0 && s1 > near && s1 < far then put out n (s1 /. len) (float_of_int cap_hit) else n in
      let s2 = (c.dist -. pz) /. vz in
      let a2 = px +. (s2 *. vx) and b2 = py +. (s2 *. vy) in
      let r2 = if c.cyl then 1.0 else c.dist *. c.dist in
      if (a2 *. a2) +. (b2 *. b2) <= r2 && s2 > near && s2 < far then put out n (s2 /. len) (float_of_int base_hit) else n
    end
    else n
  in
  if n > 0 then Stats.hit stats Stats.cone;
  n

let depth (w : Scratch.t) c o d lo = Scratch.nearest_crossing w (crossings w c o d w.crossings) lo

let hits (w : Scratch.t) c id o d lo n =
  let k = crossings w c o d w.crossings in
  let q = w.crossings in
  let n = ref n in
  for i = 0 to k - 1 do
    n := Scratch.push_ray w !n lo q.(2 * i) (int_of_float q.((2 * i) + 1)) id o d
  done;
  !n

let normal c part (p : Vec.t) =
  let n =
    if part = cap_hit then Vec.make 0. 0. 1.
    else if part = base_hit then Vec.make 0. 0. (-1.)
    else
      let q = Transform.inv_point c.ctr p in
      if c.cyl then Vec.make q.x q.y 0. else Vec.make q.x q.y (-.q.z)
  in
  Transform.normalize (Transform.normal c.ctr n)

let inside c (p : Vec.t) =
  let q = Transform.inv_point c.ctr p in
  let offset = if c.closed then -.epsilon else epsilon in
  let w2 = (q.x *. q.x) +. (q.y *. q.y) in
  let out =
    if c.cyl then w2 > 1.0 +. offset || q.z < 0.0 -. offset || q.z > 1.0 +. offset
    else w2 > (q.z *. q.z) +. offset || q.z < c.dist -. offset || q.z > 1.0 +. offset
  in
  not out

let bounds c = Transform.bounds c.ctr [| -1.; -1.; c.dist; 1.; 1.; 1. |]

let pov_box c =
  let f32 = Precision.f32 in
  Pov_box.mapped c.ctr [| f32 (-1.); f32 (-1.); f32 c.dist; f32 2.; f32 2.; f32 (1. -. c.dist) |]

let traits = { Traits.default with name = "cone" }
