(* The torus: docs/povray-rules.md §15.5 (shape/torus.cpp), with POV-Ray's quartic and its solver (§15.6). *)

type t = { major : float; minor : float; sturm : bool; tr : Transform.t }

let epsilon = Precision.epsilon
let max_distance = 1e7
let depth_tolerance = 1e-4 (* DEPTH_TOLERANCE: world depths at or below it are no hit *)
let root_tolerance = 1e-4 (* ROOT_TOLERANCE: the solver drops a root at 0 below this ratio *)

let depths (w : Scratch.t) = w.depths
let eliminated (w : Scratch.t) = Polysolv.eliminated w.quartic

(* Test_Thick_Cylinder: the caps first (when the ray is not parallel to them), then the outer and
   the inner wall, each wall's far root tried first. Written out in floats: no allocation. *)
let[@inline] on_cap px py pz vx vy vz h r1 r2 =
  let k = (h -. py) /. vy in
  let u = px +. (k *. vx) and w = pz +. (k *. vz) in
  k > epsilon && k < max_distance
  &&
  let r = (u *. u) +. (w *. w) in
  r >= r1 && r <= r2

let[@inline] on_wall py vy k h1 h2 =
  k > epsilon && k < max_distance
  &&
  let h = py +. (k *. vy) in
  h >= h1 && h <= h2

let[@inline] wall px py pz vy a b rr h1 h2 =
  let c = (px *. px) +. (pz *. pz) -. rr in
  let d = (b *. b) -. (a *. c) in
  d >= 0.
  &&
  let d = sqrt d in
  on_wall py vy ((-.b +. d) /. a) h1 h2 || on_wall py vy ((-.b -. d) /. a) h1 h2

let[@inline] thick_cylinder_f px py pz vx vy vz h1 h2 r1 r2 =
  let parallel = Float.abs vy < epsilon in
  if parallel && (py < h1 || py > h2) then false
  else if (not parallel) && (on_cap px py pz vx vy vz h2 r1 r2 || on_cap px py pz vx vy vz h1 r1 r2) then true
  else
    let a = (vx *. vx) +. (vz *. vz) in
    a > epsilon
    &&
    let b = (px *. vx) +. (pz *. vz) in
    wall px py pz vy a b r2 h1 h2 || wall px py pz vy a b r1 h1 h2

let thick_cylinder (p : Vec.t) (v : Vec.t) h1 h2 r1 r2 = thick_cylinder_f p.x p.y p.z v.x v.y v.z h1 h2 r1 r2

let solve (w : Scratch.t) t (o : Vec.t) (d : Vec.t) =
  let m = t.tr in
  (* MInvTransPoint, MInvTransDirection, then the direction times the reciprocal of its length *)
  let px = (o.x *. m.i00) +. (o.y *. m.i10) +. (o.z *. m.i20) +. m.i30 in
  let py = (o.x *. m.i01) +. (o.y *. m.i11) +. (o.z *. m.i21) +. m.i31 in
  let pz = (o.x *. m.i02) +. (o.y *. m.i12) +. (o.z *. m.i22) +. m.i32 in
  let vx = (d.x *. m.i00) +. (d.y *. m.i10) +. (d.z *. m.i20) in
  let vy = (d.x *. m.i01) +. (d.y *. m.i11) +. (d.z *. m.i21) in
  let vz = (d.x *. m.i02) +. (d.y *. m.i12) +. (d.z *. m.i22) in
  let len = sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
  let k = 1. /. len in
  let vx = vx *. k and vy = vy *. k and vz = vz *. k in
  let big = t.major and small = t.minor in
  let r1 = if big < small then 0. else (big -. small) *. (big -. small) in
  let r2 = (big +. small) *. (big +. small) in
  if not (thick_cylinder_f px py pz vx vy vz (-.small) small r1 r2) then -1
  else begin
    (* start from just outside the sphere of radius R + 2r around the torus, for precision *)
    let bound = big +. small +. small in
    let dist2 = (px *. px) +. (py *. py) +. (pz *. pz) in
    let closer = if dist2 > bound *. bound then sqrt dist2 -. bound else 0. in
    let px = px +. (closer *. vx) and py = py +. (closer *. vy) and pz = pz +. (closer *. vz) in
    let rr2 = big *. big and sr2 = small *. small in
    let py2 = py *. py and dy2 = vy *. vy and pdy2 = py *. vy in
    let k1 = (px *. px) +. (pz *. pz) +. py2 -. rr2 -. sr2 in
    let k2 = (px *. vx) +. (pz *. vz) +. pdy2 in
    let c = w.coeffs in
    c.(0) <- 1.;
    c.(1) <- 4. *. k2;
    c.(2) <- 2. *. (k1 +. (2. *. ((k2 *. k2) +. (rr2 *. dy2))));
    c.(3) <- 4. *. ((k2 *. k1) +. (2. *. rr2 *. pdy2));
    c.(4) <- (k1 *. k1) +. (4. *. rr2 *. (py2 -. sr2));
    let n = Polysolv.solve w.quartic c 4 ~sturm:t.sturm ~eps:root_tolerance w.roots in
    for i = 0 to n - 1 do
      w.depths.(i) <- (w.roots.(n - 1 - i) +. closer) /. len
    done;
    n
  end

let intersections (w : Scratch.t) t ~near o d out =
  let n = solve w t o d in
  let k = ref 0 in
  for i = 0 to n - 1 do
    let x = w.depths.(i) in
    if x > near && x < max_distance then begin
      out.(!k) <- x;
      incr k
    end
  done;
  !k

let nearest (w : Scratch.t) t ~near o d lo =
  let n = solve w t o d in
  let best = ref infinity in
  for i = 0 to n - 1 do
    let x = w.depths.(i) in
    if x > near && x < max_distance && x >= lo && x < !best then best := x
  done;
  !best

let normal t (p : Vec.t) =
  let q = Transform.inv_point t.tr p in
  let dist = sqrt ((q.x *. q.x) +. (q.z *. q.z)) in
  let n =
    if dist > epsilon then Vec.make (q.x -. (t.major *. q.x /. dist)) q.y (q.z -. (t.major *. q.z /. dist))
    else Vec.make q.x q.y q.z
  in
  Transform.normalize (Transform.normal t.tr n)

let inside t (p : Vec.t) =
  let q = Transform.inv_point t.tr p in
  let r = sqrt ((q.x *. q.x) +. (q.z *. q.z)) in
  let r2 = (q.y *. q.y) +. ((r -. t.major) *. (r -. t.major)) in
  r2 <= t.minor *. t.minor

let box t =
  let r2 = t.major +. t.minor and r1 = t.minor in
  [| -.r2; -.r1; -.r2; r2; r1; r2 |]

(* One intersection, counted as POV-Ray counts it ("Torus", "Torus Bound", "Roots tested …
   eliminated"); the raw depths are left in [w.depths]. *)
let counted_solve (w : Scratch.t) t o d =
  let stats = w.stats in
  Stats.test stats Stats.torus;
  Stats.test stats Stats.torus_bound;
  let n = solve w t o d in
  if n >= 0 then begin
    Stats.hit stats Stats.torus_bound;
    Stats.test stats Stats.roots;
    if eliminated w then Stats.hit stats Stats.roots;
    if n > 0 then Stats.hit stats Stats.torus
  end;
  n

(* the torus's own depth limit, 1e-4 in world units (§15.5); the robust mode takes every depth *)
let near_limit (w : Scratch.t) = if w.robust then 0. else depth_tolerance

let crossings (w : Scratch.t) t o d out =
  let n = counted_solve w t o d in
  let near = near_limit w and ds = w.depths in
  let k = ref 0 in
  for i = 0 to n - 1 do
    let x = ds.(i) in
    if x > near && x < 1e7 then begin
      out.(!k) <- x;
      incr k
    end
  done;
  !k

let depth (w : Scratch.t) t o d lo =
  let n = counted_solve w t o d in
  let near = near_limit w and ds = w.depths in
  let best = ref infinity in
  for i = 0 to n - 1 do
    let x = ds.(i) in
    if x > near && x < 1e7 && x >= lo && x < !best then best := x
  done;
  !best

let hits (w : Scratch.t) t id o d lo n =
  let k = crossings w t o d w.crossings in
  let n = ref n in
  for i = 0 to k - 1 do
    n := Scratch.push_ray w !n lo w.crossings.(i) (-1) id o d
  done;
  !n

let bounds t = Transform.bounds t.tr (box t)
let pov_box t = let b = box t in Pov_box.mapped t.tr (Pov_box.of_min_max (Array.sub b 0 3) (Array.sub b 3 3))

let traits = { Traits.default with name = "torus"; sturm = Sturm_flag }

(* Torus::CalcUV: in torus space, u from the angle about the y axis (1 at −x going round from
   there, decreasing towards +z), v from the angle about the tube's core circle *)
let uv t p =
  let q = Transform.inv_point t.tr p in
  let x = q.x and y = q.y and z = q.z in
  let u = 1.0 -. ((Float.atan2 z x +. Float.pi) /. (2. *. Float.pi)) in
  let len = sqrt ((x *. x) +. (z *. z)) in
  let x = len -. t.major in
  let v = (Float.atan2 y x +. Float.pi) /. (2. *. Float.pi) in
  Vec.make u v 0.
