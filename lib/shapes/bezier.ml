(* The bicubic patch: POV-Ray's shape/bezier.cpp. A Bezier patch of 16 control points in world
   space (every modifier moves the points), cut into flat enough subpatches, each crossed as two
   triangles with the normal interpolated from the patch's own normals at their corners. Type 0
   subdivides for every ray; type 1 keeps the subdivision as a tree of bounding spheres. *)

let bezier_epsilon = 1.0e-10
let bezier_tolerance = 1.0e-5

type node =
  | Leaf of { lc : Vec.t; lr2 : float; corners : Vec.t array; u0 : float; u1 : float; v0 : float; v1 : float }
  | Interior of { ic : Vec.t; ir2 : float; children : node array }

type t = { patch_type : int; u_steps : int; v_steps : int; flatness : float; cp : Vec.t array; st : float array; tree : node option }

(* ---------------------------------------------------------------------------------------------- *)
(* vector arithmetic in POV-Ray's order *)

let sub (a : Vec.t) (b : Vec.t) = Vec.make (a.x -. b.x) (a.y -. b.y) (a.z -. b.z)
let dot (a : Vec.t) (b : Vec.t) = (a.x *. b.x) +. (a.y *. b.y) +. (a.z *. b.z)
let cross (b : Vec.t) (c : Vec.t) = Vec.make ((b.y *. c.z) -. (b.z *. c.y)) ((b.z *. c.x) -. (b.x *. c.z)) ((b.x *. c.y) -. (b.y *. c.x))
let scale (a : Vec.t) k = Vec.make (a.x *. k) (a.y *. k) (a.z *. k)
let half (b : Vec.t) (c : Vec.t) = Vec.make (0.5 *. (b.x +. c.x)) (0.5 *. (b.y +. c.y)) (0.5 *. (b.z +. c.z))
let at (p : Vec.t array) i j = p.((4 * i) + j)

(* bezier_bounding_sphere: the mean of the 16 points and the largest squared distance from it *)
let bounding_sphere (p : Vec.t array) =
  let xc = ref 0. and yc = ref 0. and zc = ref 0. in
  Array.iter
    (fun (q : Vec.t) ->
      xc := !xc +. q.x;
      yc := !yc +. q.y;
      zc := !zc +. q.z)
    p;
  let xc = !xc /. 16.0 and yc = !yc /. 16.0 and zc = !zc /. 16.0 in
  let r0 = ref 0.0 in
  Array.iter
    (fun (q : Vec.t) ->
      let x0 = q.x -. xc and y0 = q.y -. yc and z0 = q.z -. zc in
      let r1 = (x0 *. x0) +. (y0 *. y0) +. (z0 *. z0) in
      if r1 > !r0 then r0 := r1)
    p;
  (Vec.make xc yc zc, !r0)

(* spherical_bounds_check: a ray starting inside the sphere, or passing within it (whichever way
   it points) *)
let sphere_check (o : Vec.t) (d : Vec.t) (c : Vec.t) r2 =
  let x = c.x -. o.x and y = c.y -. o.y and z = c.z -. o.z in
  let dist1 = (x *. x) +. (y *. y) +. (z *. z) in
  dist1 < r2
  ||
  let dist2 = (x *. d.x) +. (y *. d.y) +. (z *. d.z) in
  let dist2 = dist2 *. dist2 in
  dist2 > 0. && dist1 -. dist2 <= r2 +. bezier_epsilon

(* the de Casteljau halves along the first index (u) and along the second (v) *)
let split_curve a b c d =
  let t1 = half a b and h = half b c in
  let t12 = half t1 h and t22 = half c d in
  let t21 = half h t22 in
  let m = half t12 t21 in
  ([| a; t1; t12; m |], [| m; t21; t22; d |])

(* the two halves of a patch split along one index: the control point (i, j) of curve i is at
   [stride_i·i + stride_j·j], in the patch and in both halves *)
let split_along p ~stride_i ~stride_j =
  let first = Array.make 16 Vec.zero and second = Array.make 16 Vec.zero in
  for i = 0 to 3 do
    let base = stride_i * i in
    let a, b = split_curve p.(base) p.(base + stride_j) p.(base + (2 * stride_j)) p.(base + (3 * stride_j)) in
    for j = 0 to 3 do
      let k = base + (stride_j * j) in
      first.(k) <- a.(j);
      second.(k) <- b.(j)
    done
  done;
  (first, second)

let split_left_right p = split_along p ~stride_i:1 ~stride_j:4
let split_up_down p = split_along p ~stride_i:4 ~stride_j:1

let length (a : Vec.t) = sqrt (dot a a)

(* subpatch_normal: the plane through three points, None when they are (nearly) collinear *)
let plane_of v1 v2 v3 =
  let a = sub v1 v2 and b = sub v3 v2 in
  let r = cross a b in
  let l = dot r r in
  if l <= bezier_epsilon *. dot a a *. dot b b then None
  else
    let k = 1.0 /. sqrt l in
    let n = scale r k in
    Some (n, 0.0 -. dot n v1)

(* determine_subpatch_flatness: the largest distance of a control point from the plane of three
   distinct corners, or −1 *)
let flatness_of p =
  let eps = Precision.epsilon in
  let c00 = at p 0 0 and c03 = at p 0 3 and c33 = at p 3 3 and c30 = at p 3 0 in
  let corners =
    if Float.abs (length (sub c00 c03)) < eps then
      if Float.abs (length (sub c00 c33)) < eps then None
      else if Float.abs (length (sub c33 c30)) < eps then None
      else Some (c00, c33, c30)
    else if Float.abs (length (sub c03 c30)) < eps then None
    else Some (c00, c03, c30)
  in
  match corners with
  | None -> -1.0
  | Some (a, b, c) -> (
      match plane_of a b c with
      | None -> -1.0
      | Some (n, d) ->
          let dist = ref 0.0 in
          Array.iter
            (fun q ->
              let l = length n in
              let t = if Float.abs l < eps then 0.0 else (dot q n +. d) /. l in
              let t = Float.abs t in
              if t > !dist then dist := t)
            p;
          !dist)

let flat_enough b p =
  let d = flatness_of p in
  d >= 0.0 && d < b.flatness

(* bezier_value's normal: the cross product of the tangents at (u, v), unit, or (1, 0, 0) *)
let patch_normal b u0 v0 =
  let c = [| 1.0; 3.0; 3.0; 1.0 |] in
  let u = Array.make 4 1.0 and uu = Array.make 4 1.0 and v = Array.make 4 1.0 and vv = Array.make 4 1.0 in
  let du = Array.make 4 0.0 and duu = Array.make 4 0.0 and dv = Array.make 4 0.0 and dvv = Array.make 4 0.0 in
  for i = 1 to 3 do
    u.(i) <- u.(i - 1) *. u0;
    uu.(i) <- uu.(i - 1) *. (1.0 -. u0);
    v.(i) <- v.(i - 1) *. v0;
    vv.(i) <- vv.(i - 1) *. (1.0 -. v0);
    du.(i) <- Float.of_int i *. u.(i - 1);
    duu.(i) <- Float.of_int (-i) *. uu.(i - 1);
    dv.(i) <- Float.of_int i *. v.(i - 1);
    dvv.(i) <- Float.of_int (-i) *. vv.(i - 1)
  done;
  let ux = ref 0. and uy = ref 0. and uz = ref 0. and vx = ref 0. and vy = ref 0. and vz = ref 0. in
  for i = 0 to 3 do
    for j = 0 to 3 do
      let k = c.(i) *. c.(j) in
      let ut = u.(i) *. uu.(3 - i) and vt = v.(j) *. vv.(3 - j) in
      let q = at b.cp i j in
      let t = k *. vt *. ((du.(i) *. uu.(3 - i)) +. (u.(i) *. duu.(3 - i))) in
      ux := !ux +. (t *. q.x);
      uy := !uy +. (t *. q.y);
      uz := !uz +. (t *. q.z);
      let t = k *. ut *. ((dv.(j) *. vv.(3 - j)) +. (v.(j) *. dvv.(3 - j))) in
      vx := !vx +. (t *. q.x);
      vy := !vy +. (t *. q.y);
      vz := !vz +. (t *. q.z)
    done
  done;
  let u1 = Vec.make !ux !uy !uz and v1 = Vec.make !vx !vy !vz in
  let n = cross u1 v1 in
  let t = dot n n in
  if t > bezier_epsilon *. dot u1 u1 *. dot v1 v1 then scale n (1.0 /. sqrt t) else Vec.make 1. 0. 0.

(* MInvers3: the inverse of the 3×3 matrix of rows b0, b1, b2 (as rows again), None when singular *)
let invert3 (a : Vec.t) (b : Vec.t) (c : Vec.t) =
  let o0x = (b.y *. c.z) -. (b.z *. c.y) and o1x = -.((a.y *. c.z) -. (a.z *. c.y)) and o2x = (a.y *. b.z) -. (a.z *. b.y) in
  let o0y = -.((b.x *. c.z) -. (b.z *. c.x)) and o1y = (a.x *. c.z) -. (a.z *. c.x) and o2y = -.((a.x *. b.z) -. (a.z *. b.x)) in
  let o0z = (b.x *. c.y) -. (b.y *. c.x) and o1z = -.((a.x *. c.y) -. (a.y *. c.x)) and o2z = (a.x *. b.y) -. (a.y *. b.x) in
  let det =
    (a.x *. b.y *. c.z) +. (a.y *. b.z *. c.x) +. (a.z *. b.x *. c.y) -. (a.z *. b.y *. c.x) -. (a.x *. b.z *. c.y) -. (a.y *. b.x *. c.z)
  in
  if Float.abs det < 1.0e-10 then None
  else
    let k = 1.0 /. det in
    Some (Vec.make (o0x *. k) (o0y *. k) (o0z *. k), Vec.make (o1x *. k) (o1y *. k) (o1z *. k), Vec.make (o2x *. k) (o2y *. k) (o2z *. k))

(* intersect_subpatch: the triangle (v0, v1, v2) with the patch parameters (uu, vv) at its
   corners: the depth, the point, the interpolated unit normal and patch parameters (u, v) *)
let triangle b (o : Vec.t) (d : Vec.t) v0 v1 v2 (uu0, uu1, uu2) (vv0, vv1, vv2) =
  let b0 = sub v1 v0 and b1 = sub v2 v0 in
  let b2 = cross b0 b1 in
  let dd = dot b2 b2 in
  if dd <= bezier_epsilon *. dot b1 b1 *. dot b0 b0 then None
  else
    let b2 = scale b2 (1.0 /. sqrt dd) in
    match invert3 b0 b1 b2 with
    | None -> None
    | Some (ib0, ib1, ib2) ->
        let dn = dot d ib2 in
        if Float.abs dn < bezier_epsilon then None
        else
          let depth = dot (sub v0 o) ib2 /. dn in
          if depth < bezier_tolerance then None
          else
            let p = Vec.make (o.x +. (d.x *. depth)) (o.y +. (d.y *. depth)) (o.z +. (d.z *. depth)) in
            let q = sub p v0 in
            let a = dot q ib0 and c = dot q ib1 in
            if a < 0.0 || c < 0.0 || a +. c > 1.0 then None
            else
              let r = 1.0 -. a -. c in
              let n0 = patch_normal b uu0 vv0 and n1 = patch_normal b uu1 vv1 and n2 = patch_normal b uu2 vv2 in
              let nx = 0. +. (n0.x *. r) +. (n1.x *. a) +. (n2.x *. c)
              and ny = 0. +. (n0.y *. r) +. (n1.y *. a) +. (n2.y *. c)
              and nz = 0. +. (n0.z *. r) +. (n1.z *. a) +. (n2.z *. c) in
              let n = Vec.make nx ny nz in
              let t = dot n n in
              let u = (r *. uu0) +. (a *. uu1) +. (c *. uu2) and v = (r *. vv0) +. (a *. vv1) +. (c *. vv2) in
              let n = if t > bezier_epsilon then scale n (1.0 /. sqrt t) else Vec.make 1. 0. 0. in
              Some (depth, p, n, u, v)

(* the two triangles of a flat subpatch, (P00, P03, P33) then (P00, P33, P30), each crossing
   given to [emit] in POV-Ray's push order *)
let quad b o d c00 c03 c33 c30 u0 u1 v0 v1 emit =
  (match triangle b o d c00 c03 c33 (u0, u0, u1) (v0, v1, v1) with Some (t, p, n, u, v) -> emit t p n u v | None -> ());
  match triangle b o d c00 c33 c30 (u0, u1, u1) (v0, v1, v0) with Some (t, p, n, u, v) -> emit t p n u v | None -> ()

(* Compute_Texture_UV: the patch parameters (u, v) mapped into the quadrilateral of the four
   uv_vectors [st] (u0, v0, …, u3, v3), the parameter v running from the first edge to the second
   and u from the first corner to the last *)
let texture_uv b u v =
  let st = b.st in
  let p0 = v and p1 = u in
  let u10 = st.(0) +. (p0 *. (st.(2) -. st.(0))) and u11 = st.(1) +. (p0 *. (st.(3) -. st.(1))) in
  let u20 = st.(6) +. (p0 *. (st.(4) -. st.(6))) and u21 = st.(7) +. (p0 *. (st.(5) -. st.(7))) in
  (u10 +. (p1 *. (u20 -. u10)), u11 +. (p1 *. (u21 -. u11)))

(* bezier_subdivider (type 0), and type 1 when its tree would be too big: the same subpatches in
   the same order as the tree's walk (whose leaves keep their parameter range in single precision:
   the same numbers, halves of halves of 1, to 24 splits) *)
let rec subdivide b o d p u0 u1 v0 v1 depth emit =
  let c, r2 = bounding_sphere p in
  if sphere_check o d c r2 then
    if flat_enough b p || (depth >= b.u_steps && depth >= b.v_steps) then quad b o d (at p 0 0) (at p 0 3) (at p 3 3) (at p 3 0) u0 u1 v0 v1 emit
    else if depth >= b.u_steps then begin
      let lo, hi = split_up_down p in
      let vt = (v1 +. v0) /. 2.0 in
      subdivide b o d lo u0 u1 v0 vt (depth + 1) emit;
      subdivide b o d hi u0 u1 vt v1 (depth + 1) emit
    end
    else if depth >= b.v_steps then begin
      let l, r = split_left_right p in
      let ut = (u1 +. u0) /. 2.0 in
      subdivide b o d l u0 ut v0 v1 (depth + 1) emit;
      subdivide b o d r ut u1 v0 v1 (depth + 1) emit
    end
    else begin
      let ut = (u1 +. u0) /. 2.0 and vt = (v1 +. v0) /. 2.0 in
      let l, r = split_left_right p in
      let ll, ul = split_up_down l and lr, ur = split_up_down r in
      subdivide b o d ll u0 ut v0 vt (depth + 1) emit;
      subdivide b o d ul u0 ut vt v1 (depth + 1) emit;
      subdivide b o d lr ut u1 v0 vt (depth + 1) emit;
      subdivide b o d ur ut u1 vt v1 (depth + 1) emit
    end

(* bezier_tree_builder (type 1) *)
let rec build b p u0 u1 v0 v1 depth =
  let c, r2 = bounding_sphere p in
  let leaf () =
    let f = Precision.f32 in
    Leaf { lc = c; lr2 = r2; corners = [| at p 0 0; at p 0 3; at p 3 3; at p 3 0 |]; u0 = f u0; u1 = f u1; v0 = f v0; v1 = f v1 }
  in
  if flat_enough b p || (depth >= b.u_steps && depth >= b.v_steps) then leaf ()
  else if depth >= b.u_steps then
    let lo, hi = split_up_down p in
    let vm = (v0 +. v1) /. 2.0 in
    Interior { ic = c; ir2 = r2; children = [| build b lo u0 u1 v0 vm (depth + 1); build b hi u0 u1 vm v1 (depth + 1) |] }
  else if depth >= b.v_steps then
    let l, r = split_left_right p in
    let um = (u0 +. u1) /. 2.0 in
    Interior { ic = c; ir2 = r2; children = [| build b l u0 um v0 v1 (depth + 1); build b r um u1 v0 v1 (depth + 1) |] }
  else
    let l, r = split_left_right p in
    let ll, ul = split_up_down l and lr, ur = split_up_down r in
    let um = (u0 +. u1) /. 2.0 and vm = (v0 +. v1) /. 2.0 in
    Interior
      {
        ic = c;
        ir2 = r2;
        children =
          [| build b ll u0 um v0 vm (depth + 1); build b ul u0 um vm v1 (depth + 1); build b lr um u1 v0 vm (depth + 1); build b ur um u1 vm v1 (depth + 1) |];
      }

let rec walk b o d node emit =
  match node with
  | Interior { ic; ir2; children } -> if sphere_check o d ic ir2 then Array.iter (fun n -> walk b o d n emit) children
  | Leaf { lc; lr2; corners; u0; u1; v0; v1 } ->
      if sphere_check o d lc lr2 then quad b o d corners.(0) corners.(1) corners.(2) corners.(3) u0 u1 v0 v1 emit

(* The most splits, u_steps + v_steps, of a type 1 patch whose tree is kept: at most 2^16 leaves,
   some 16 MiB. POV-Ray builds the tree whatever its size: u_steps 12 v_steps 12, 4^12 leaves,
   takes POV-Ray 28 s and 3.7 GB ("Out of memory" under 2 GiB); subdividing for every ray crosses
   the same subpatches in the same order, in bounded memory. *)
let max_tree_splits = 16

let make ~patch_type ~u_steps ~v_steps ~flatness ~st cp =
  let b = { patch_type; u_steps; v_steps; flatness; cp; st; tree = None } in
  if patch_type = 1 && max 0 u_steps + max 0 v_steps <= max_tree_splits then { b with tree = Some (build b cp 0.0 1.0 0.0 1.0 0) } else b

(* All_Intersections: every crossing, in POV-Ray's push order, to [emit] *)
let crossings (w : Scratch.t) b o d emit =
  let stats = w.stats in
  Stats.test stats Stats.bicubic;
  let found = ref false in
  let emit t p n u v =
    found := true;
    let tu, tv = texture_uv b u v in
    emit t p n tu tv
  in
  (match b.tree with None -> subdivide b o d b.cp 0.0 1.0 0.0 1.0 0 emit | Some node -> walk b o d node emit);
  if !found then Stats.hit stats Stats.bicubic

let depth (w : Scratch.t) b o d lo =
  let best = w.depths in
  best.(0) <- infinity;
  crossings w b o d (fun t p n u v ->
      (* POV-Ray takes them off its stack from the top, keeping a strictly nearer one: of equal
         depths the last pushed *)
      if t >= lo && t <= best.(0) then begin
        best.(0) <- t;
        Crossing.set w.crossing p n u v;
        w.reported <- true
      end);
  best.(0)

let hits (w : Scratch.t) b id o d lo n =
  let count = ref n in
  crossings w b o d (fun t p nn u v ->
      if t >= lo then begin
        Crossing.set w.crossing p nn u v;
        count := Scratch.push_reported w !count t id
      end);
  !count

let min_max b =
  let huge = 2e10 in
  let lo = [| huge; huge; huge |] and hi = [| -.huge; -.huge; -.huge |] in
  Array.iter
    (fun (q : Vec.t) ->
      lo.(0) <- Float.min lo.(0) q.x;
      lo.(1) <- Float.min lo.(1) q.y;
      lo.(2) <- Float.min lo.(2) q.z;
      hi.(0) <- Float.max hi.(0) q.x;
      hi.(1) <- Float.max hi.(1) q.y;
      hi.(2) <- Float.max hi.(2) q.z)
    b.cp;
  (lo, hi)

let bounds b =
  let lo, hi = min_max b in
  Array.append lo hi

let pov_box b =
  let lo, hi = min_max b in
  Pov_box.of_min_max lo hi

let traits = { Traits.default with name = "bicubic_patch"; inverse_flag = false; patch = true }
