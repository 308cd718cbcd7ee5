(* The ovus, after POV-Ray 3.7's shape/ovus.cpp: a bottom sphere, a top sphere, and between them
   the inner part of a spindle torus that joins them smoothly; each part's normal is the one
   POV-Ray computes when it finds the hit. *)

type t = {
  bottom : float;
  top : float;
  hpos : float;
  vpos : float;
  bvert : float;
  tvert : float;
  crad : float;
  sturm : bool;
  tr : Transform.t;
}

let epsilon = Precision.epsilon
let root_tolerance = 1e-4 (* ROOT_TOLERANCE: order reduction, and the torus root check *)

let set_up bottom top =
  if top < 2.0 *. bottom then
    if bottom > top then begin
      let crad = 2.0 *. bottom in
      let vpos = (2.0 *. top) -. bottom -. (top *. top /. (2.0 *. bottom)) in
      let hpos = sqrt ((bottom *. bottom) -. (vpos *. vpos)) in
      let bvert = -.vpos in
      let distance = crad -. top in
      let tvert = ((bottom -. vpos) *. top /. distance) +. bottom in
      Some { bottom; top; hpos; vpos; bvert; tvert; crad; sturm = false; tr = Transform.identity }
    end
    else begin
      let crad = 2.0 *. top in
      let vpos = (-2.0 *. top) +. bottom +. (1.5 *. top *. top /. bottom) in
      let hpos = sqrt ((top *. top) -. ((vpos -. bottom) *. (vpos -. bottom))) in
      let tvert = (2.0 *. bottom) -. vpos in
      let distance = crad -. bottom in
      let bvert = -.vpos *. bottom /. distance in
      Some { bottom; top; hpos; vpos; bvert; tvert; crad; sturm = false; tr = Transform.identity }
    end
  else None

let transform v m = { v with tr = Transform.compose v.tr m }

let part_bottom = 1
let part_top = 2
let part_joint = 3

(* One sphere of the ovus against the ray (P, D) in ovus space: its two depths, or none; the
   test of Intersect_Ovus_Spheres, which keeps rays starting inside or heading towards it *)
let sphere_depths (px, py, pz) (dx, dy, dz) cy r2 =
  let ax = 0. -. px and ay = cy -. py and az = 0. -. pz in
  let oc2 = (ax *. ax) +. (ay *. ay) +. (az *. az) in
  let tca = (ax *. dx) +. (ay *. dy) +. (az *. dz) in
  if oc2 < r2 || tca > epsilon then
    let thc2 = r2 -. oc2 +. (tca *. tca) in
    if thc2 > epsilon then
      let hc = sqrt thc2 in
      Some (tca -. hc, tca +. hc)
    else None
  else None

(* Intersect_Ovus_Spheres then All_Intersections: the (world depth, part) pairs in POV-Ray's push
   order written into [out] (room for 12), their number returned; −100 marks a depth not found *)
let intersect (w : Scratch.t) v (o : Vec.t) (d : Vec.t) (out : float array) =
  let m = v.tr in
  let p = Transform.inv_point m o in
  let dv = Transform.inv_direction m d in
  let len = sqrt ((dv.x *. dv.x) +. (dv.y *. dv.y) +. (dv.z *. dv.z)) in
  let k = 1.0 /. len in
  let dx = dv.x *. k and dy = dv.y *. k and dz = dv.z *. k in
  let pt = (p.x, p.y, p.z) and dir = (dx, dy, dz) in
  let yat t = p.y +. (t *. dy) in
  let d1 = ref (-100.) and d2 = ref (-100.) and d3 = ref (-100.) in
  let d4 = ref (-100.) and d5 = ref (-100.) and d6 = ref (-100.) in
  let lcount = ref 0 in
  (* Sqr(BottomRadius): Padj is −P, the same squares *)
  (match sphere_depths pt dir 0. (v.bottom *. v.bottom) with
  | Some (a, b) ->
      d1 := a;
      d2 := b;
      if yat a < v.bvert then incr lcount;
      if yat b < v.bvert then incr lcount
  | None -> ());
  if !lcount <= 1 then begin
    (match sphere_depths pt dir v.bottom (v.top *. v.top) with
    | Some (a, b) ->
        d3 := a;
        d4 := b;
        if yat a > v.tvert then incr lcount;
        if yat b > v.tvert then incr lcount
    | None -> ());
    if !lcount <= 1 then begin
      (* the joint: a spindle torus about the y axis at height vpos *)
      let ax = p.x and ay = p.y -. v.vpos and az = p.z in
      let r2 = v.hpos *. v.hpos and sr2 = v.crad *. v.crad in
      let py2 = ay *. ay and dy2 = dy *. dy and pdy2 = ay *. dy in
      let k1 = (ax *. ax) +. (az *. az) +. py2 -. r2 -. sr2 in
      let k2 = (ax *. dx) +. (az *. dz) +. pdy2 in
      let c = w.coeffs in
      c.(0) <- 1.0;
      c.(1) <- 4.0 *. k2;
      c.(2) <- 2.0 *. (k1 +. (2.0 *. ((k2 *. k2) +. (r2 *. dy2))));
      c.(3) <- 4.0 *. ((k2 *. k1) +. (2.0 *. r2 *. pdy2));
      c.(4) <- (k1 *. k1) +. (4.0 *. r2 *. (py2 -. sr2));
      let st = w.stats in
      Stats.test st Stats.roots;
      let n = Polysolv.solve w.quartic c 4 ~sturm:v.sturm ~eps:root_tolerance w.roots in
      if Polysolv.eliminated w.quartic then Stats.hit st Stats.roots;
      (* only the inner part of the torus (the lemon), between the two spheres *)
      for i = n - 1 downto 0 do
        let r = w.roots.(i) in
        let ix = p.x +. (r *. dx) and iy = p.y +. (r *. dy) and iz = p.z +. (r *. dz) in
        if iy > v.bvert && iy < v.tvert then begin
          let horizontal = sqrt ((ix *. ix) +. (iz *. iz)) in
          let oc2 = ((horizontal +. v.hpos) *. (horizontal +. v.hpos)) +. ((iy -. v.vpos) *. (iy -. v.vpos)) in
          if Float.abs (oc2 -. (v.crad *. v.crad)) < root_tolerance then if !d5 < 0. then d5 := r else d6 := r
        end
      done
    end
  end;
  let n = ref 0 in
  let push t part =
    out.(2 * !n) <- t /. len;
    out.((2 * !n) + 1) <- Float.of_int part;
    incr n
  in
  if !d1 > epsilon && yat !d1 < v.bvert then push !d1 part_bottom;
  if !d2 > epsilon && yat !d2 < v.bvert then push !d2 part_bottom;
  if !d3 > epsilon && yat !d3 > v.tvert then push !d3 part_top;
  if !d4 > epsilon && yat !d4 > v.tvert then push !d4 part_top;
  if !d5 > epsilon then push !d5 part_joint;
  if !d6 > epsilon then push !d6 part_joint;
  !n

(* the normal of the part hit at the ovus-space point [q], before the transform *)
let local_normal v part (q : Vec.t) =
  if part = part_bottom then
    let k = 1.0 /. v.bottom in
    Vec.make (q.x *. k) (q.y *. k) (q.z *. k)
  else if part = part_top then
    let k = 1.0 /. v.top in
    Vec.make (q.x *. k) ((q.y -. v.bottom) *. k) (q.z *. k)
  else
    let x = q.x and y = q.y -. v.vpos and z = q.z in
    let horizontal = sqrt ((x *. x) +. (z *. z)) in
    let x = x +. (x *. v.hpos /. horizontal) and z = z +. (z *. v.hpos /. horizontal) in
    Transform.normalize (Vec.make x y z)

let normal v part (p : Vec.t) = Transform.normalize (Transform.normal v.tr (local_normal v part (Transform.inv_point v.tr p)))

(* Ovus::Inside: within a sphere, or within the joint between its heights (not inverted) *)
let inside v (p : Vec.t) =
  let q = Transform.inv_point v.tr p in
  let in_bottom = (q.x *. q.x) +. (q.y *. q.y) +. (q.z *. q.z) < v.bottom *. v.bottom in
  let oy = q.y -. v.bottom in
  let in_top = (q.x *. q.x) +. (oy *. oy) +. (q.z *. q.z) < v.top *. v.top in
  let in_joint =
    q.y > v.bvert && q.y < v.tvert
    &&
    let horizontal = sqrt ((q.x *. q.x) +. (q.z *. q.z)) in
    ((horizontal +. v.hpos) *. (horizontal +. v.hpos)) +. ((q.y -. v.vpos) *. (q.y -. v.vpos)) < v.crad *. v.crad
  in
  in_bottom || in_top || in_joint

(* Compute_BBox: the widest of the joint and the spheres, from −bottom to bottom + top *)
let biggest v =
  let b = v.crad -. v.hpos in
  let b = if b < v.bottom then v.bottom else b in
  if b < v.top then v.top else b

let bounds v =
  let b = biggest v in
  Transform.bounds v.tr [| -.b; -.v.bottom; -.b; b; v.bottom +. v.top; b |]

let pov_box v =
  let b = biggest v and f = Precision.f32 in
  Pov_box.mapped v.tr [| f (-.b); f (-.v.bottom); f (-.b); f (2.0 *. b); f ((2.0 *. v.bottom) +. v.top); f (2.0 *. b) |]

let counted (w : Scratch.t) v o d out =
  let st = w.stats in
  Stats.test st Stats.ovus;
  let n = intersect w v o d out in
  if n > 0 then Stats.hit st Stats.ovus;
  n

let depth (w : Scratch.t) v o d lo =
  let out = Array.make 12 0. in
  let n = counted w v o d out in
  let best = ref infinity and part = ref (-1) in
  for i = n - 1 downto 0 do
    let t = out.(2 * i) in
    if t < !best && t >= lo then begin
      best := t;
      part := int_of_float out.((2 * i) + 1)
    end
  done;
  w.part <- !part;
  !best

let hits (w : Scratch.t) v id o d lo n =
  let out = Array.make 12 0. in
  let k = counted w v o d out in
  let n = ref n in
  for i = 0 to k - 1 do
    n := Scratch.push_ray w !n lo out.(2 * i) (int_of_float out.((2 * i) + 1)) id o d
  done;
  !n

(* Ovus::CalcUV: as a sphere about the point top/2 up the axis *)
let uv v (p : Vec.t) =
  let q = Transform.inv_point v.tr p in
  let x = q.x and y = q.y -. (v.top /. 2.0) and z = q.z in
  let len = sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
  if len = 0.0 then Vec.make 0. 0. 0.
  else
    let x = x /. len and y = y /. len and z = z /. len in
    let phi = 0.5 +. (Float.asin y /. Float.pi) in
    let l = (x *. x) +. (z *. z) in
    let theta =
      if l > epsilon then
        let l = sqrt l in
        if z = 0.0 then if x > 0. then 0.0 else Float.pi /. (2. *. Float.pi)
        else
          let th = Float.acos (x /. l) in
          let th = if z < 0.0 then (2. *. Float.pi) -. th else th in
          th /. (2. *. Float.pi)
      else 0.
    in
    Vec.make theta phi 0.

let traits = { Traits.default with name = "ovus"; sturm = Sturm_bool }
