(* The sphere sweep, after POV-Ray 3.7's shape/sphsweep.cpp: the modeling spheres become
   segments (a centre and a radius polynomial in u ∈ [0, 1] each) and single spheres closing
   them; a ray meets the single spheres, each segment's closing surfaces and its sides (a
   polynomial in u, of degree 2 or 10), and the hits inside the sweep are dropped. *)

type interpolation = Linear | Catmull_rom | B_spline

type t = {
  interpolation : interpolation;
  spheres : (Vec.t * float) array;  (** the modeling spheres, moved by the modifiers POV-Ray applies to them *)
  tolerance : float;
  trans : Transform.t option;
}

type segment = {
  ncoefs : int;  (** 2 (linear) or 4 (cubic) *)
  cc : Vec.t array;  (** Center_Coef: the centre polynomial's coefficients, u⁰ first *)
  rc : float array;  (** Radius_Coef *)
  c0 : Vec.t;  (** the closing sphere at u = 0 … *)
  r0 : float;
  c1 : Vec.t;  (** … and at u = 1 *)
  r1 : float;
  dc0 : Vec.t;  (** Center_Deriv and Radius_Deriv at u = 0 … *)
  dr0 : float;
  dc1 : Vec.t;  (** … and at u = 1 *)
  dr1 : float;
}

type compiled = { sweep : t; segments : segment array; singles : (Vec.t * float) array; ubits : int }

let epsilon = Precision.epsilon
let depth_tolerance = 1e-6 (* DEPTH_TOLERANCE: the default of [tolerance] *)
let zero_tolerance = 1e-4 (* a linear segment's side slope below this is met as a sphere *)
let max_distance = 1e7

let make interpolation spheres tolerance = { interpolation; spheres; tolerance; trans = None }

(* the spline matrices, entry by entry as POV-Ray writes them *)
let catmull_rom =
  [| [| 0.0 /. 2.0; 2.0 /. 2.0; 0.0 /. 2.0; 0.0 /. 2.0 |]; [| -1.0 /. 2.0; 0.0 /. 2.0; 1.0 /. 2.0; 0.0 /. 2.0 |];
     [| 2.0 /. 2.0; -5.0 /. 2.0; 4.0 /. 2.0; -1.0 /. 2.0 |]; [| -1.0 /. 2.0; 3.0 /. 2.0; -3.0 /. 2.0; 1.0 /. 2.0 |] |]

let b_matrix =
  [| [| 1.0 /. 6.0; 4.0 /. 6.0; 1.0 /. 6.0; 0.0 /. 6.0 |]; [| -3.0 /. 6.0; 0.0 /. 6.0; 3.0 /. 6.0; 0.0 /. 6.0 |];
     [| 3.0 /. 6.0; -6.0 /. 6.0; 3.0 /. 6.0; 0.0 /. 6.0 |]; [| -1.0 /. 6.0; 3.0 /. 6.0; -3.0 /. 6.0; 1.0 /. 6.0 |] |]

let vadd (a : Vec.t) (b : Vec.t) = Vec.make (a.x +. b.x) (a.y +. b.y) (a.z +. b.z)
let vsub (a : Vec.t) (b : Vec.t) = Vec.make (a.x -. b.x) (a.y -. b.y) (a.z -. b.z)
let vdot (a : Vec.t) (b : Vec.t) = (a.x *. b.x) +. (a.y *. b.y) +. (a.z *. b.z)

(* VAddScaled: a + k·b *)
let vaddk (a : Vec.t) k (b : Vec.t) = Vec.make (a.x +. (k *. b.x)) (a.y +. (k *. b.y)) (a.z +. (k *. b.z))

(* the polynomial coefficients of one segment, then its closing spheres and end derivatives *)
let segment ncoefs (cc : Vec.t array) (rc : float array) =
  let c1 = ref cc.(0) and r1 = ref rc.(0) in
  for k = 1 to ncoefs - 1 do
    c1 := vadd !c1 cc.(k);
    r1 := !r1 +. rc.(k)
  done;
  let dc1 = ref cc.(1) and dr1 = ref rc.(1) in
  for k = 2 to ncoefs - 1 do
    let f = Float.of_int k in
    dc1 := vaddk !dc1 f cc.(k);
    dr1 := !dr1 +. (f *. rc.(k))
  done;
  { ncoefs; cc; rc; c0 = cc.(0); r0 = rc.(0); c1 = !c1; r1 = !r1; dc0 = cc.(1); dr0 = rc.(1); dc1 = !dc1; dr1 = !dr1 }

let bits n =
  let rec go b = if 1 lsl b > n then b else go (b + 1) in
  go 0

(* SphereSweep::Compute *)
let compile s =
  let m = s.spheres in
  let segments =
    match s.interpolation with
    | Linear ->
        Array.init
          (Array.length m - 1)
          (fun i ->
            let ci, ri = m.(i) and cn, rn = m.(i + 1) in
            segment 2 [| ci; vsub cn ci |] [| ri; rn -. ri |])
    | Catmull_rom | B_spline ->
        let mat = if s.interpolation = Catmull_rom then catmull_rom else b_matrix in
        Array.init
          (Array.length m - 3)
          (fun i ->
            let cc = Array.make 4 (Vec.make 0. 0. 0.) and rc = Array.make 4 0. in
            for k = 0 to 3 do
              let c, r = m.(i) in
              let acc = ref (Vec.make (c.x *. mat.(k).(0)) (c.y *. mat.(k).(0)) (c.z *. mat.(k).(0))) in
              let racc = ref (r *. mat.(k).(0)) in
              for j = 1 to 3 do
                let c, r = m.(i + j) in
                acc := vaddk !acc mat.(k).(j) c;
                racc := !racc +. (mat.(k).(j) *. r)
              done;
              cc.(k) <- !acc;
              rc.(k) <- !racc
            done;
            segment 4 cc rc)
  in
  let n = Array.length segments in
  let singles = Array.init (n + 1) (fun i -> if i < n then (segments.(i).c0, segments.(i).r0) else (segments.(n - 1).c1, segments.(n - 1).r1)) in
  { sweep = s; segments; singles; ubits = 50 - bits (n + 1) }

(* the modifiers: without a transform, translate, rotate and a uniform scale move the modeling
   spheres (Translate, Rotate, Scale); anything else starts the transform, which every later
   modifier composes into *)
type op = Translate of Vec.t | Rotate | Scale of Vec.t | Other

let move s op m =
  match (s.trans, op) with
  | None, Translate v -> { s with spheres = Array.map (fun (c, r) -> (vadd c v, r)) s.spheres }
  | None, Rotate -> { s with spheres = Array.map (fun (c, r) -> (Transform.point m c, r)) s.spheres }
  | None, Scale (v : Vec.t) when v.x = v.y && v.x = v.z ->
      { s with spheres = Array.map (fun ((c : Vec.t), r) -> (Vec.make (c.x *. v.x) (c.y *. v.x) (c.z *. v.x), r *. v.x)) s.spheres }
  | None, (Scale _ | Other) -> { s with trans = Some m }
  | Some t, _ -> { s with trans = Some (Transform.compose t m) }

(* The part codes: what was hit, which sphere or segment, and the segment's u where the hit's
   normal needs it, packed in an integer a float holds exactly (below 2⁵³). *)
let kind_single = 0
let kind_start = 1
let kind_end = 2
let kind_side = 3
let kind_sphere_at = 4

let umax c = Float.of_int ((1 lsl c.ubits) - 1)
let code c kind index u = (((index lsl c.ubits) + Float.to_int (Float.round (u *. umax c))) * 8) + kind

(* The nearest hit's part needs no float: an OCaml int holds the bits of u itself (u ∈ [2⁻⁵¹¹, 1]
   has bit 61 set and bit 62 clear, so 61 bits remain), with one bit for the kind, as a negative
   number below −1; the segment is found again at the hit point. Other u fall back to [code]. *)
let bit61 = 1 lsl 61

let exact c kind index u =
  let bits = Int64.to_int (Int64.bits_of_float u) in
  if u > 0. && bits land bit61 <> 0 then -(2 + ((bits land (bit61 - 1)) lsl 1) + if kind = kind_sphere_at then 1 else 0)
  else code c kind index u

let parts c kind index u = (code c kind index u, exact c kind index u)
let plain_part c kind index = let k = code c kind index 0. in (k, k)

(* Intersect_Sphere: the two crossings of one sphere as (t, normal) with the normal
   (point − centre)/radius, or none *)
let sphere_crossings (o : Vec.t) (d : Vec.t) (centre : Vec.t) radius add part =
  let r2 = radius *. radius in
  let oc = vsub centre o in
  let oc2 = vdot oc oc and tca = vdot oc d in
  if oc2 >= r2 && tca < epsilon then false
  else
    let thc2 = r2 -. oc2 +. (tca *. tca) in
    if thc2 > epsilon then begin
      let hc = sqrt thc2 in
      let k = 1.0 /. radius in
      let one t =
        let p = vaddk o t d in
        let n = vsub p centre in
        (t, Vec.make (n.x *. k) (n.y *. k) (n.z *. k))
      in
      let t0, n0 = one (tca -. hc) in
      let t1, n1 = one (tca +. hc) in
      add t0 n0 part;
      add t1 n1 part;
      true
    end
    else false

let lcm6 = [| 60.; 10.; 4.; 3.; 4.; 10.; 60. |]
let lcm10 = [| 2520.; 252.; 56.; 21.; 12.; 10.; 12.; 21.; 56.; 252.; 2520. |]

(* bezier_01: no root in [0, 1] when the polynomial's Bernstein coefficients all have one sign;
   otherwise Solve_Polynomial, counted in [stats] when given *)
let bezier_01 ?stats work degree (coef : float array) roots =
  let lcm = if degree = 6 then lcm6 else lcm10 in
  let d = Array.init (degree + 1) (fun i -> coef.(i) *. lcm.(i)) in
  let rec go i nonneg nonpos =
    if i > degree then 0
    else
      let nonneg = nonneg && d.(degree - i) >= 0. and nonpos = nonpos && d.(degree - i) <= 0. in
      if not (nonneg || nonpos) then begin
        let n = Polysolv.solve work coef degree ~sturm:true ~eps:1e-10 roots in
        (match stats with
        | Some (st : Stats.t) ->
            Stats.test st Stats.roots;
            if Polysolv.eliminated work then Stats.hit st Stats.roots
        | None -> ());
        n
      end
      else begin
        for j = 0 to degree - i - 1 do
          d.(j) <- d.(j) +. d.(j + 1)
        done;
        go (i + 1) nonneg nonpos
      end
  in
  go 0 true true

let normalize = Transform.normalize

(* the roots in [0, 1], in their order *)
let in_unit roots n = List.filter (fun u -> not (u < 0.0 || u > 1.0)) (Array.to_list (Array.sub roots 0 n))

(* the centre and radius of a cubic segment at u *)
let cubic_sphere sg u =
  let cc = sg.cc and rc = sg.rc in
  let c = vaddk cc.(0) u cc.(1) in
  let c = vaddk c (u *. u) cc.(2) in
  let c = vaddk c (u *. u *. u) cc.(3) in
  let r = (rc.(3) *. u *. u *. u) +. (rc.(2) *. u *. u) +. (rc.(1) *. u) +. rc.(0) in
  (c, r)

(* Intersect_Segment: the crossings of segment [i] as (t, normal, part) through [add] *)
let segment_crossings (st : Stats.t) work c i (o : Vec.t) (d : Vec.t) add =
  let sg = c.segments.(i) in
  let cap dc (centre : Vec.t) radius dr kind =
    let dot1 = vdot d dc in
    if Float.abs dot1 > epsilon then begin
      let v = vsub o centre in
      let dot2 = vdot v dc in
      let t = -.(dot2 +. (radius *. dr)) /. dot1 in
      if t > -.max_distance && t < max_distance then begin
        let p = vaddk o t d in
        let dcen = vsub p centre in
        if vdot dcen dcen < radius *. radius then
          let n = if kind = kind_start then Vec.make (-1.0 *. dc.x) (-1.0 *. dc.y) (-1.0 *. dc.z) else dc in
          add t (normalize n) (plain_part c kind i)
      end
    end
  in
  cap sg.dc0 sg.c0 sg.r0 sg.dr0 kind_start;
  cap sg.dc1 sg.c1 sg.r1 sg.dr1 kind_end;
  let roots = Array.make 10 0. in
  let solved n =
    Stats.test st Stats.roots;
    if Polysolv.eliminated work then Stats.hit st Stats.roots;
    n
  in
  let cc = sg.cc and rc = sg.rc in
  let v = vsub o cc.(0) in
  if sg.ncoefs = 2 then begin
    let b = vdot cc.(1) d *. -2.0 in
    let cq = vdot v d *. 2.0 in
    let dd = vdot cc.(1) cc.(1) -. (rc.(1) *. rc.(1)) in
    let e = (vdot v cc.(1) +. (rc.(0) *. rc.(1))) *. -2.0 in
    let f = vdot v v -. (rc.(0) *. rc.(0)) in
    let coef = [| (4.0 *. (dd *. dd)) -. (b *. b *. dd); (4.0 *. dd *. e) -. (2.0 *. b *. cq *. dd); (e *. e) -. (b *. cq *. e) +. (b *. b *. f) |] in
    let n = solved (Polysolv.solve work coef 2 ~sturm:true ~eps:1e-10 roots) in
    List.iter
      (fun u ->
        let fp0 = (2.0 *. dd *. u) +. e and fp1 = b in
        if Float.abs fp1 > zero_tolerance then begin
          let t = -.fp0 /. fp1 in
          if t > -.max_distance && t < max_distance then begin
            let p = vaddk o t d in
            let centre = vaddk cc.(0) u cc.(1) in
            add t (normalize (vsub p centre)) (parts c kind_side i u)
          end
        end
        else
          let centre = vaddk cc.(0) u cc.(1) in
          let radius = (rc.(1) *. u) +. rc.(0) in
          ignore (sphere_crossings o d centre radius add (parts c kind_sphere_at i u)))
      (in_unit roots n)
  end
  else begin
    let b = vdot cc.(3) d *. -2.0 in
    let cq = vdot cc.(2) d *. -2.0 in
    let dq = vdot cc.(1) d *. -2.0 in
    let e = vdot v d *. 2.0 in
    let f = vdot cc.(3) cc.(3) -. (rc.(3) *. rc.(3)) in
    let g = (vdot cc.(3) cc.(2) -. (rc.(3) *. rc.(2))) *. 2.0 in
    let h = (vdot cc.(3) cc.(1) *. 2.0) +. vdot cc.(2) cc.(2) -. (2.0 *. rc.(3) *. rc.(1)) -. (rc.(2) *. rc.(2)) in
    let iq = (vdot cc.(3) v -. vdot cc.(2) cc.(1) +. (rc.(3) *. rc.(0)) +. (rc.(2) *. rc.(1))) *. -2.0 in
    let j = ((vdot cc.(2) v +. (rc.(2) *. rc.(0))) *. -2.0) +. vdot cc.(1) cc.(1) -. (rc.(1) *. rc.(1)) in
    let k = (vdot cc.(1) v +. (rc.(1) *. rc.(0))) *. -2.0 in
    let l = vdot v v -. (rc.(0) *. rc.(0)) in
    let sq x = x *. x in
    let b2 = sq b and c2 = sq cq and d2 = sq dq in
    let coef =
      [|
        (36.0 *. sq f) -. (9.0 *. f *. b2);
        (60.0 *. f *. g) -. (6.0 *. g *. b2) -. (18.0 *. b *. cq *. f);
        (48.0 *. f *. h) +. (25.0 *. sq g) -. (3.0 *. h *. b2) -. (13.0 *. b *. cq *. g) -. (8.0 *. f *. c2) -. (18.0 *. b *. dq *. f);
        (36.0 *. f *. iq) +. (40.0 *. g *. h) -. (18.0 *. b *. f *. e) -. (8.0 *. b *. cq *. h) -. (6.0 *. g *. c2) -. (14.0 *. b *. dq *. g)
        -. (14.0 *. cq *. dq *. f);
        (24.0 *. f *. j) +. (30.0 *. g *. iq) +. (16.0 *. sq h) -. (15.0 *. b *. g *. e) -. (12.0 *. cq *. f *. e) +. (3.0 *. j *. b2)
        -. (3.0 *. b *. cq *. iq) -. (4.0 *. h *. c2) -. (10.0 *. b *. dq *. h) -. (11.0 *. cq *. dq *. g) -. (5.0 *. f *. d2);
        (12.0 *. f *. k) +. (20.0 *. g *. j) +. (24.0 *. h *. iq) -. (12.0 *. b *. h *. e) -. (10.0 *. cq *. g *. e) -. (6.0 *. dq *. f *. e)
        +. (6.0 *. k *. b2) +. (2.0 *. b *. cq *. j) -. (2.0 *. iq *. c2) -. (6.0 *. b *. dq *. iq) -. (8.0 *. cq *. dq *. h) -. (4.0 *. g *. d2);
        (10.0 *. g *. k) +. (16.0 *. h *. j) +. (9.0 *. sq iq) -. (9.0 *. b *. iq *. e) -. (8.0 *. cq *. h *. e) -. (5.0 *. dq *. g *. e)
        +. (9.0 *. l *. b2) +. (7.0 *. b *. cq *. k) -. (2.0 *. b *. dq *. j) -. (5.0 *. cq *. dq *. iq) -. (3.0 *. h *. d2);
        (8.0 *. h *. k) +. (12.0 *. iq *. j) -. (6.0 *. b *. j *. e) -. (6.0 *. cq *. iq *. e) -. (4.0 *. dq *. h *. e) +. (12.0 *. b *. cq *. l)
        +. (2.0 *. k *. c2) +. (2.0 *. b *. dq *. k) -. (2.0 *. cq *. dq *. j) -. (2.0 *. iq *. d2);
        (6.0 *. iq *. k) +. (4.0 *. sq j) -. (3.0 *. b *. k *. e) -. (4.0 *. cq *. j *. e) -. (3.0 *. dq *. iq *. e) +. (4.0 *. l *. c2)
        +. (6.0 *. b *. dq *. l) +. (cq *. dq *. k) -. (j *. d2);
        (4.0 *. j *. k) -. (2.0 *. cq *. k *. e) -. (2.0 *. dq *. j *. e) +. (4.0 *. cq *. dq *. l);
        sq k -. (dq *. k *. e) +. (l *. d2);
      |]
    in
    let n = bezier_01 ~stats:st work 10 coef roots in
    List.iter
      (fun u ->
        let centre, radius = cubic_sphere sg u in
        ignore (sphere_crossings o d centre radius add (parts c kind_sphere_at i u)))
      (in_unit roots n)
  end

(* Find_Valid_Points: along the sorted crossings (their normals [ns]), keep those where the ray
   enters the sweep from outside every part or leaves the last part it was in; the first and the
   last are always kept. The indices kept, in order. *)
let valid_points (ns : Vec.t array) (d : Vec.t) =
  let idx = Array.init (Array.length ns) (fun i -> i) in
  let num = ref (Array.length ns) and inside = ref 1 and i = ref 1 in
  while !i < !num - 1 do
    let keep =
      if vdot ns.(idx.(!i)) d < 0.0 then begin
        let k = !inside = 0 in
        incr inside;
        k
      end
      else begin
        let k = !inside = 1 in
        decr inside;
        k
      end
    in
    if keep then incr i
    else begin
      Array.blit idx (!i + 1) idx !i (!num - !i - 1);
      decr num
    end
  done;
  Array.sub idx 0 !num

(* SphereSweep::All_Intersections: the kept (world depth, part) pairs in their sorted order,
   beyond the sweep's tolerance *)
let intersect (w : Scratch.t) c (o : Vec.t) (d : Vec.t) =
  let st = w.stats in
  let o', d', len =
    match c.sweep.trans with
    | None -> (o, d, 1.0)
    | Some m ->
        let p = Transform.inv_point m o and dv = Transform.inv_direction m d in
        let len = sqrt ((dv.x *. dv.x) +. (dv.y *. dv.y) +. (dv.z *. dv.z)) in
        let k = 1.0 /. len in
        (p, Vec.make (dv.x *. k) (dv.y *. k) (dv.z *. k), len)
  in
  let nsph = Array.length c.singles and nseg = Array.length c.segments in
  let max_isect = ((nsph + nseg) * 2) + 64 in
  let ts = ref [] in
  let count = ref 0 in
  (* the single spheres' crossings are taken when within ±1e7, while there is room for two *)
  Array.iteri
    (fun i (centre, radius) ->
      let found = ref [] in
      let add t n p = found := (t, n, p) :: !found in
      if sphere_crossings o' d' centre radius add (plain_part c kind_single i) then
        if !count + 2 <= max_isect then
          List.iter
            (fun ((t, _, _) as x) ->
              if t > -.max_distance && t < max_distance then begin
                ts := x :: !ts;
                incr count
              end)
            (List.rev !found))
    c.singles;
  let work = Polysolv.create () in
  for i = 0 to nseg - 1 do
    let found = ref [] and k = ref 0 in
    let add t n p = found := (t, n, p) :: !found; incr k in
    segment_crossings st work c i o' d' add;
    if !count + !k <= max_isect then begin
      ts := !found @ !ts;
      count := !count + !k
    end
  done;
  if !count = 0 then [||]
  else begin
    let all = Array.of_list (List.rev !ts) in
    (* QSORT by depth (glibc's merge sort: stable) *)
    let all = List.stable_sort (fun (a, _, _) (b, _, _) -> Float.compare a b) (Array.to_list all) |> Array.of_list in
    let tarr = Array.map (fun (t, _, _) -> t) all and narr = Array.map (fun (_, nv, _) -> nv) all and parr = Array.map (fun (_, _, p) -> p) all in
    let kept = valid_points narr d' in
    let out = ref [] in
    Array.iter
      (fun i ->
        let t = tarr.(i) /. len in
        if t > c.sweep.tolerance then out := (t, fst parr.(i), snd parr.(i)) :: !out)
      kept;
    Array.of_list (List.rev !out)
  end

(* the normal POV-Ray stored with the hit of [part] at the world point [p] *)
let normal c part (p : Vec.t) =
  let q = match c.sweep.trans with None -> p | Some m -> Transform.inv_point m p in
  let kind, index, u =
    if part < -1 then begin
      (* an exact u: the segment is the one whose sphere at u passes nearest the point *)
      let v = -part - 2 in
      let u = Int64.float_of_bits (Int64.of_int ((v lsr 1) lor bit61)) in
      let off i =
        let sg = c.segments.(i) in
        let centre, radius = if sg.ncoefs = 2 then (vaddk sg.cc.(0) u sg.cc.(1), (sg.rc.(1) *. u) +. sg.rc.(0)) else cubic_sphere sg u in
        let e = vsub q centre in
        Float.abs (vdot e e -. (radius *. radius))
      in
      let best = ref 0 in
      for i = 1 to Array.length c.segments - 1 do
        if off i < off !best then best := i
      done;
      ((if v land 1 = 1 then kind_sphere_at else kind_side), !best, u)
    end
    else
      let rest = part lsr 3 in
      (part land 7, rest lsr c.ubits, Float.of_int (rest land ((1 lsl c.ubits) - 1)) /. umax c)
  in
  let n =
    if kind = kind_single then
      let centre, radius = c.singles.(index) in
      let k = 1.0 /. radius and v = vsub q centre in
      Vec.make (v.x *. k) (v.y *. k) (v.z *. k)
    else
      let sg = c.segments.(index) in
      if kind = kind_start then normalize (Vec.make (-1.0 *. sg.dc0.x) (-1.0 *. sg.dc0.y) (-1.0 *. sg.dc0.z))
      else if kind = kind_end then normalize sg.dc1
      else if kind = kind_side then normalize (vsub q (vaddk sg.cc.(0) u sg.cc.(1)))
      else
        let centre, radius = if sg.ncoefs = 2 then (vaddk sg.cc.(0) u sg.cc.(1), (sg.rc.(1) *. u) +. sg.rc.(0)) else cubic_sphere sg u in
        let k = 1.0 /. radius and v = vsub q centre in
        Vec.make (v.x *. k) (v.y *. k) (v.z *. k)
  in
  match c.sweep.trans with None -> n | Some m -> normalize (Transform.normal m n)

(* SphereSweep::Inside (not inverted): some sphere of some segment holds the point, which is a
   root in [0, 1] of |P − C(u)|² − R(u)² *)
let inside c (p : Vec.t) =
  let q = match c.sweep.trans with None -> p | Some m -> Transform.inv_point m p in
  let work = Polysolv.create () and roots = Array.make 6 0. in
  Array.exists
    (fun sg ->
      let cc = sg.cc and rc = sg.rc in
      let v = vsub q cc.(0) in
      let n, coef =
        if sg.ncoefs = 2 then
          let coef = [| vdot cc.(1) cc.(1) -. (rc.(1) *. rc.(1)); (vdot v cc.(1) +. (rc.(0) *. rc.(1))) *. -2.0; vdot v v -. (rc.(0) *. rc.(0)) |] in
          (Polysolv.solve work coef 2 ~sturm:true ~eps:1e-10 roots, coef)
        else
          let coef =
            [|
              vdot cc.(3) cc.(3) -. (rc.(3) *. rc.(3));
              (vdot cc.(3) cc.(2) -. (rc.(3) *. rc.(2))) *. 2.0;
              (vdot cc.(3) cc.(1) *. 2.0) +. vdot cc.(2) cc.(2) -. (2.0 *. rc.(3) *. rc.(1)) -. (rc.(2) *. rc.(2));
              (vdot cc.(3) v -. vdot cc.(2) cc.(1) +. (rc.(3) *. rc.(0)) +. (rc.(2) *. rc.(1))) *. -2.0;
              ((vdot cc.(2) v +. (rc.(2) *. rc.(0))) *. -2.0) +. vdot cc.(1) cc.(1) -. (rc.(1) *. rc.(1));
              (vdot cc.(1) v +. (rc.(1) *. rc.(0))) *. -2.0;
              vdot v v -. (rc.(0) *. rc.(0));
            |]
          in
          (bezier_01 work 6 coef roots, coef)
      in
      ignore coef;
      let rec any j = j < n && ((roots.(j) >= 0.0 && roots.(j) <= 1.0) || any (j + 1)) in
      any 0)
    c.segments

(* Compute_BBox: the modeling spheres' extent (twice their radii for Catmull-Rom), then the
   transform if there is one *)
let extent c =
  let lo = [| infinity; infinity; infinity |] and hi = [| neg_infinity; neg_infinity; neg_infinity |] in
  let k = if c.sweep.interpolation = Catmull_rom then 2. else 1. in
  Array.iter
    (fun ((ctr : Vec.t), r) ->
      let rr = k *. r in
      let mn a b = if b < a then b else a and mx a b = if a < b then b else a in
      lo.(0) <- mn lo.(0) (ctr.x -. rr);
      lo.(1) <- mn lo.(1) (ctr.y -. rr);
      lo.(2) <- mn lo.(2) (ctr.z -. rr);
      hi.(0) <- mx hi.(0) (ctr.x +. rr);
      hi.(1) <- mx hi.(1) (ctr.y +. rr);
      hi.(2) <- mx hi.(2) (ctr.z +. rr))
    c.sweep.spheres;
  (lo, hi)

let bounds c =
  let lo, hi = extent c in
  let b = Array.append lo hi in
  match c.sweep.trans with None -> b | Some m -> Transform.bounds m b

let pov_box c =
  let lo, hi = extent c in
  let b = Pov_box.of_min_max lo hi in
  match c.sweep.trans with None -> b | Some m -> Pov_box.mapped m b

let counted (w : Scratch.t) c o d =
  let st = w.stats in
  Stats.test st Stats.sphere_sweep;
  let h = intersect w c o d in
  if Array.length h > 0 then Stats.hit st Stats.sphere_sweep;
  h

let depth (w : Scratch.t) c o d lo =
  let h = counted w c o d in
  let best = ref infinity and part = ref (-1) in
  for i = Array.length h - 1 downto 0 do
    let t, _, p = h.(i) in
    if t < !best && t >= lo then begin
      best := t;
      part := p
    end
  done;
  w.part <- !part;
  !best

let hits (w : Scratch.t) c id o d lo n =
  Array.fold_left (fun n (t, p, _) -> Scratch.push_ray w n lo t p id o d) n (counted w c o d)

let traits = { Traits.default with name = "sphere_sweep" }
