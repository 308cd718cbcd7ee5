(* A ray against a blob (shape/blob.cpp All_Intersections): the intervals where its elements
   act, sorted, and the quartic of each interval. *)

open Blob

let epsilon = Precision.epsilon
let bound_huge = 2e10
let max_distance = 1e7
let small_tolerance = 1e-3 (* SMALL_TOLERANCE of frame.h *)
let root_epsilon = 1e-11 (* the root elimination ratio All_Intersections passes the solver *)


(* the room of one intersection, grown to this blob's size *)
let room (w : Scratch.t) c =
  let r = w.blob and n = Array.length c.elems in
  if Array.length r.bounds < (2 * n) + 2 then begin
    r.bounds <- Array.make ((2 * n) + 2) 0.;
    r.marks <- Array.make ((2 * n) + 2) 0
  end;
  if Array.length r.fcoeffs < 5 * n then r.fcoeffs <- Array.make (5 * n) 0.;
  if Array.length r.queue < node_count c + 1 then r.queue <- Array.make (node_count c + 1) 0;
  r

(* ---------------------------------------------------------------------------------------------- *)
(* Where each element is active along the ray (intersect_element and its cases): the entry and
   exit depths left in [acc.(5)] and [acc.(6)]. *)

let set_span (r : Scratch.blob_room) tmin tmax =
  r.acc.(5) <- tmin;
  r.acc.(6) <- tmax

(* the span between the depths [tmax] and [tmin] of a sphere or ellipsoid, each below [mindist]
   taken as 0, in increasing order: none when the two are equal *)
let[@inline] clamped_span r mindist tmax tmin =
  let tmax = if tmax < mindist then 0. else tmax in
  let tmin = if tmin < mindist then 0. else tmin in
  if tmax = tmin then false
  else begin
    if tmax < tmin then set_span r tmax tmin else set_span r tmin tmax;
    true
  end

let sphere_span r e px py pz dx dy dz mindist =
  let vx = px -. e.ox and vy = py -. e.oy and vz = pz -. e.oz in
  let b = (vx *. dx) +. (vy *. dy) +. (vz *. dz) in
  let t = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
  let d = (b *. b) -. t +. e.erad2 in
  if d < epsilon then false
  else
    let d = sqrt d in
    clamped_span r mindist (-.b +. d) (-.b -. d)

(* coordinate [k] of the ray in an element's space: 0–2 the point (MInvTransPoint), 3–5 the
   direction (MInvTransDirection), one float at a time so that nothing is allocated *)
let[@inline] in_element e px py pz dx dy dz k =
  let m = e.etr in
  match k with
  | 0 -> (px *. m.i00) +. (py *. m.i10) +. (pz *. m.i20) +. m.i30
  | 1 -> (px *. m.i01) +. (py *. m.i11) +. (pz *. m.i21) +. m.i31
  | 2 -> (px *. m.i02) +. (py *. m.i12) +. (pz *. m.i22) +. m.i32
  | 3 -> (dx *. m.i00) +. (dy *. m.i10) +. (dz *. m.i20)
  | 4 -> (dx *. m.i01) +. (dy *. m.i11) +. (dz *. m.i21)
  | _ -> (dx *. m.i02) +. (dy *. m.i12) +. (dz *. m.i22)

let ellipsoid_span r e px py pz dx dy dz mindist =
  let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 and qz = in_element e px py pz dx dy dz 2 in
  let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
  let len = sqrt ((ux *. ux) +. (uy *. uy) +. (uz *. uz)) in
  let k = 1. /. len in
  let ux = ux *. k and uy = uy *. k and uz = uz *. k in
  let vx = qx -. e.ox and vy = qy -. e.oy and vz = qz -. e.oz in
  let b = (vx *. ux) +. (vy *. uy) +. (vz *. uz) in
  let t = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
  let d = (b *. b) -. t +. e.erad2 in
  if d < epsilon then false
  else
    let d = sqrt d in
    clamped_span r mindist ((-.b +. d) /. len) ((-.b -. d) /. len)

(* intersect_hemisphere: the sphere's span cut by the plane z = 0 (base: the half z ≤ 0) or
   z = len (apex: the half above) *)
let hemisphere_span r e px py pz dx dy dz mindist =
  let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 and qz = in_element e px py pz dx dy dz 2 in
  let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
  let len = sqrt ((ux *. ux) +. (uy *. uy) +. (uz *. uz)) in
  let k = 1. /. len in
  let ux = ux *. k and uy = uy *. k and uz = uz *. k in
  let base = match e.ekind with Base_hemisphere -> true | Sphere | Ellipsoid | Apex_hemisphere | Cylinder -> false in
  let qz = if base then qz else qz -. e.elen in
  let b = (qx *. ux) +. (qy *. uy) +. (qz *. uz) in
  let t = (qx *. qx) +. (qy *. qy) +. (qz *. qz) in
  let d = (b *. b) -. t +. e.erad2 in
  if d < epsilon then false
  else
    let d = sqrt d in
    let tmax = -.b +. d and tmin = -.b -. d in
    let tmin, tmax = if tmax < tmin then (tmax, tmin) else (tmin, tmax) in
    let z1 = qz +. (tmin *. uz) and z2 = qz +. (tmax *. uz) in
    (* which side of the plane is the element's: z ≤ 0 for the base, z > 0 for the apex *)
    let inside1 = if base then z1 >= 0.0 else z1 <= 0.0 and inside2 = if base then z2 >= 0.0 else z2 <= 0.0 in
    if inside1 && inside2 then false
    else if (not inside1) && not inside2 then begin
      set_span r (tmin /. len) (tmax /. len);
      true
    end
    else
      let t = -.qz /. uz in
      let tmin, tmax = if inside1 then ((if t < mindist then 0.0 else t), tmax) else (tmin, if t < mindist then 0.0 else t) in
      set_span r (tmin /. len) (tmax /. len);
      true

let cylinder_span r e px py pz dx dy dz mindist =
  let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 and qz = in_element e px py pz dx dy dz 2 in
  let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
  let len = sqrt ((ux *. ux) +. (uy *. uy) +. (uz *. uz)) in
  let k = 1. /. len in
  let ux = ux *. k and uy = uy *. k and uz = uz *. k in
  let tmin = ref bound_huge and tmax = ref (-.bound_huge) in
  let keep t =
    if t < !tmin then tmin := t;
    if t > !tmax then tmax := t
  in
  let a = (ux *. ux) +. (uy *. uy) in
  if a > epsilon then begin
    let b = (qx *. ux) +. (qy *. uy) in
    let c = (qx *. qx) +. (qy *. qy) -. e.erad2 in
    let d = (b *. b) -. (a *. c) in
    if d > epsilon then begin
      let d = sqrt d in
      let t = (-.b +. d) /. a in
      let h = qz +. (t *. uz) in
      if h >= 0.0 && h <= e.elen then keep t;
      let t = (-.b -. d) /. a in
      let h = qz +. (t *. uz) in
      if h >= 0.0 && h <= e.elen then keep t
    end
  end;
  if Float.abs uz > epsilon then begin
    let t = -.qz /. uz in
    let u = qx +. (t *. ux) and v = qy +. (t *. uy) in
    if (u *. u) +. (v *. v) <= e.erad2 then keep t;
    let t = (e.elen -. qz) /. uz in
    let u = qx +. (t *. ux) and v = qy +. (t *. uy) in
    if (u *. u) +. (v *. v) <= e.erad2 then keep t
  end;
  let tmin = !tmin /. len and tmax = !tmax /. len in
  let tmin = if tmin < mindist then 0.0 else tmin and tmax = if tmax < mindist then 0.0 else tmax in
  if tmin >= tmax then false
  else begin
    set_span r tmin tmax;
    true
  end

let element_span (w : Scratch.t) r e px py pz dx dy dz mindist =
  let s = w.stats in
  Stats.test s Stats.blob_element;
  let hit =
    match e.ekind with
    | Sphere -> sphere_span r e px py pz dx dy dz mindist
    | Ellipsoid -> ellipsoid_span r e px py pz dx dy dz mindist
    | Base_hemisphere | Apex_hemisphere -> hemisphere_span r e px py pz dx dy dz mindist
    | Cylinder -> cylinder_span r e px py pz dx dy dz mindist
  in
  if hit then Stats.hit s Stats.blob_element;
  hit

(* one depth [t] with mark [m] put in the sorted list of [cnt] entries, searched from [from]: it is
   written at [cnt] first (which stops the search), then moved down to its place, which is
   returned *)
let[@inline] place (bd : float array) (mk : int array) cnt from (t : float) m =
  bd.(cnt) <- t;
  mk.(cnt) <- m;
  let k = ref from in
  while t > bd.(!k) do
    incr k
  done;
  if !k < cnt then begin
    let k0 = !k in
    Array.blit bd k0 bd (k0 + 1) (cnt - k0);
    Array.blit mk k0 mk (k0 + 1) (cnt - k0);
    bd.(k0) <- t;
    mk.(k0) <- m
  end;
  !k

(* insert_hit: the entry and exit of element [idx] put in the sorted list of [cnt] entries *)
let insert_hit (r : Scratch.blob_room) idx t0 t1 cnt =
  let bd = r.bounds and mk = r.marks in
  let k0 = place bd mk cnt 0 t0 (2 * idx) in
  if k0 < cnt then begin
    ignore (place bd mk (cnt + 1) (k0 + 1) t1 ((2 * idx) + 1));
    cnt + 2
  end
  else begin
    bd.(cnt + 1) <- t1;
    mk.(cnt + 1) <- (2 * idx) + 1;
    cnt + 2
  end

(* determine_influences: every element, or those the hierarchy reaches (its nodes taken from the
   top of a stack, the children of a node pushed in order when the ray passes within its sphere) *)
let influences (w : Scratch.t) r c px py pz dx dy dz mindist =
  let cnt = ref 0 in
  let tr = c.tree in
  if tr.root < 0 then
    Array.iteri
      (fun i e -> if element_span w r e px py pz dx dy dz mindist then cnt := insert_hit r i r.acc.(5) r.acc.(6) !cnt)
      c.elems
  else begin
    let q = r.queue and s = w.stats in
    q.(0) <- tr.root;
    let size = ref 1 in
    while !size > 0 do
      decr size;
      let nd = q.(!size) in
      let ne = tr.entries.(nd) in
      if ne <= 0 then begin
        let i = tr.first.(nd) in
        if element_span w r c.elems.(i) px py pz dx dy dz mindist then cnt := insert_hit r i r.acc.(5) r.acc.(6) !cnt
      end
      else
        for j = 0 to ne - 1 do
          let ch = tr.kids.(tr.first.(nd) + j) in
          Stats.test s Stats.blob_bound;
          let vx = tr.cx.(ch) -. px and vy = tr.cy.(ch) -. py and vz = tr.cz.(ch) -. pz in
          let b = (vx *. dx) +. (vy *. dy) +. (vz *. dz) in
          let t = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
          if t -. (b *. b) <= tr.r2.(ch) then begin
            Stats.hit s Stats.blob_bound;
            q.(!size) <- ch;
            incr size
          end
        done
    done
  end;
  !cnt

(* an element's quartic along the (shifted, scaled) ray, written at [5·index] of [fcoeffs] *)
let element_quartic (r : Scratch.blob_room) e px py pz dx dy dz max_bound =
  let t0, t1, t2 =
    match e.ekind with
    | Sphere ->
        let vx = px -. e.ox and vy = py -. e.oy and vz = pz -. e.oz in
        ((vx *. vx) +. (vy *. vy) +. (vz *. vz), (vx *. dx) +. (vy *. dy) +. (vz *. dz), max_bound *. max_bound)
    | Ellipsoid ->
        let vx = in_element e px py pz dx dy dz 0 -. e.ox and vy = in_element e px py pz dx dy dz 1 -. e.oy in
        let vz = in_element e px py pz dx dy dz 2 -. e.oz in
        let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
        ((vx *. vx) +. (vy *. vy) +. (vz *. vz), (vx *. ux) +. (vy *. uy) +. (vz *. uz), (ux *. ux) +. (uy *. uy) +. (uz *. uz))
    | Base_hemisphere | Apex_hemisphere ->
        let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 and qz = in_element e px py pz dx dy dz 2 in
        let qz = match e.ekind with Apex_hemisphere -> qz -. e.elen | Sphere | Ellipsoid | Base_hemisphere | Cylinder -> qz in
        let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
        ((qx *. qx) +. (qy *. qy) +. (qz *. qz), (qx *. ux) +. (qy *. uy) +. (qz *. uz), (ux *. ux) +. (uy *. uy) +. (uz *. uz))
    | Cylinder ->
        let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 in
        let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 in
        ((qx *. qx) +. (qy *. qy), (qx *. ux) +. (qy *. uy), (ux *. ux) +. (uy *. uy))
  in
  let c0 = e.c0 and c1 = e.c1 and c2 = e.c2 in
  let f = r.fcoeffs and j = 5 * e.index in
  f.(j) <- c0 *. t2 *. t2;
  f.(j + 1) <- 4.0 *. c0 *. t1 *. t2;
  f.(j + 2) <- (2.0 *. c0 *. ((2.0 *. t1 *. t1) +. (t0 *. t2))) +. (c1 *. t2);
  f.(j + 3) <- 2.0 *. t1 *. ((2.0 *. c0 *. t0) +. c1);
  f.(j + 4) <- (t0 *. ((c0 *. t0) +. c1)) +. c2

let push_found (r : Scratch.blob_room) n t =
  if n >= Array.length r.found then begin
    let bigger = Array.make (2 * Array.length r.found) 0. in
    Array.blit r.found 0 bigger 0 n;
    r.found <- bigger
  end;
  r.found.(n) <- t;
  n + 1

(* one interval between two bounds: the Bézier hull test, then the quartic's roots within it *)
let interval (w : Scratch.t) (r : Scratch.blob_room) c bd i len start max_bound n =
  let acc = r.acc in
  let l = bd.(i) in
  let wd = bd.(i + 1) -. l in
  let c0 = acc.(0) and c1 = acc.(1) and c2 = acc.(2) and c3 = acc.(3) and c4 = acc.(4) in
  let n0 = c0 *. wd *. wd *. wd *. wd in
  let n1 = (c1 +. (4.0 *. c0 *. l)) *. wd *. wd *. wd in
  let n2 = ((3.0 *. l *. ((2.0 *. c0 *. l) +. c1)) +. c2) *. wd *. wd in
  let n3 = ((2.0 *. l *. ((2.0 *. l *. ((c0 *. l) +. (0.75 *. c1))) +. c2)) +. c3) *. wd in
  let n4 = (l *. ((l *. ((l *. ((c0 *. l) +. c1)) +. c2)) +. c3)) +. c4 in
  let dk0 = n4 in
  let dk1 = n4 +. (0.25 *. n3) in
  let dk2 = n4 +. (0.50 *. (n3 +. (n2 /. 3.0))) in
  let dk3 = n4 +. (0.50 *. ((1.5 *. n3) +. n2 +. (0.5 *. n1))) in
  let dk4 = n4 +. n3 +. n2 +. n1 +. n0 in
  if (dk0 >= 0.0 && dk1 >= 0.0 && dk2 >= 0.0 && dk3 >= 0.0 && dk4 >= 0.0) || (dk0 <= 0.0 && dk1 <= 0.0 && dk2 <= 0.0 && dk3 <= 0.0 && dk4 <= 0.0)
  then false
  else begin
    let s = w.stats in
    Stats.test s Stats.roots;
    let k = Polysolv.solve w.quartic acc 4 ~sturm:c.csturm ~eps:root_epsilon w.roots in
    if Polysolv.eliminated w.quartic then Stats.hit s Stats.roots;
    let found = ref false in
    let mindist = if w.robust then 0. else depth_tolerance in
    for j = 0 to k - 1 do
      let dist = w.roots.(j) in
      if dist >= bd.(i) && dist <= bd.(i + 1) then begin
        let dist = ((dist *. max_bound) +. start) /. len in
        if dist > mindist && dist < max_distance then begin
          n := push_found r !n dist;
          found := true
        end
      end
    done;
    !found
  end

(* All_Intersections: the depths found, in [w.blob.found]; [child] (a CSG member) takes every
   interval, a blob on its own stops at the first one with a root, all later ones being farther *)
let intersect (w : Scratch.t) c ~child (o : Vec.t) (d : Vec.t) =
  let s = w.stats in
  Stats.test s Stats.blob;
  let mindist = if w.robust then 0. else depth_tolerance in
  let px, py, pz, dx, dy, dz, len =
    match c.ctr with
    | Some m ->
        let px = (o.x *. m.i00) +. (o.y *. m.i10) +. (o.z *. m.i20) +. m.i30 in
        let py = (o.x *. m.i01) +. (o.y *. m.i11) +. (o.z *. m.i21) +. m.i31 in
        let pz = (o.x *. m.i02) +. (o.y *. m.i12) +. (o.z *. m.i22) +. m.i32 in
        let dx = (d.x *. m.i00) +. (d.y *. m.i10) +. (d.z *. m.i20) in
        let dy = (d.x *. m.i01) +. (d.y *. m.i11) +. (d.z *. m.i21) in
        let dz = (d.x *. m.i02) +. (d.y *. m.i12) +. (d.z *. m.i22) in
        let len = sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
        let k = 1. /. len in
        (px, py, pz, dx *. k, dy *. k, dz *. k, len)
    | None -> (o.x, o.y, o.z, d.x, d.y, d.z, 1.0)
  in
  let r = room w c in
  let cnt = influences w r c px py pz dx dy dz mindist in
  if cnt = 0 then 0
  else begin
    let bd = r.bounds and mk = r.marks in
    let start = if bd.(0) < small_tolerance then 0. else bd.(0) in
    for i = 0 to cnt - 1 do
      bd.(i) <- bd.(i) -. start
    done;
    let px = px +. (start *. dx) and py = py +. (start *. dy) and pz = pz +. (start *. dz) in
    let max_bound = ref bd.(0) in
    for i = 0 to cnt - 1 do
      if bd.(i) > !max_bound then max_bound := bd.(i)
    done;
    let dx, dy, dz, max_bound =
      if !max_bound <> 0. then begin
        let mb = !max_bound in
        for i = 0 to cnt - 1 do
          bd.(i) <- bd.(i) /. mb
        done;
        (dx *. mb, dy *. mb, dz *. mb, mb)
      end
      else (dx, dy, dz, 1.)
    in
    let acc = r.acc and f = r.fcoeffs in
    acc.(0) <- 0.;
    acc.(1) <- 0.;
    acc.(2) <- 0.;
    acc.(3) <- 0.;
    acc.(4) <- -.c.thresh;
    let n = ref 0 in
    let rec step i in_flag found =
      if i >= cnt then found
      else
        let e = c.elems.(mk.(i) lsr 1) in
        let j = 5 * e.index in
        let in_flag, skip =
          if mk.(i) land 1 = 0 then begin
            element_quartic r e px py pz dx dy dz max_bound;
            for k = 0 to 4 do
              acc.(k) <- acc.(k) +. f.(j + k)
            done;
            (in_flag + 1, false)
          end
          else begin
            for k = 0 to 4 do
              acc.(k) <- acc.(k) -. f.(j + k)
            done;
            (in_flag - 1, in_flag - 1 = 0)
          end
        in
        if skip || (i + 1 < cnt && Float.abs (bd.(i) -. bd.(i + 1)) < epsilon) then step (i + 1) in_flag found
        else
          let found = interval w r c bd i len start max_bound n || found in
          if found && not child then true else step (i + 1) in_flag found
    in
    let found = step 0 0 false in
    if found then Stats.hit s Stats.blob;
    !n
  end

(* ---------------------------------------------------------------------------------------------- *)
(* What the tracer asks. *)

(* a blob on its own is tested only through its box: one with no component of positive strength
   and no transform has an empty box (negative lengths), which no ray enters *)
let depth (w : Scratch.t) c o d lo =
  if c.cbox.(3) < 0. || c.cbox.(4) < 0. || c.cbox.(5) < 0. then infinity
  else
  let n = intersect w c ~child:false o d in
  let best = ref infinity in
  let f = w.blob.found in
  for i = n - 1 downto 0 do
    let x = f.(i) in
    if x < !best && x >= lo then best := x
  done;
  !best

let hits (w : Scratch.t) c id o d lo n =
  let k = intersect w c ~child:true o d in
  let n = ref n in
  for i = 0 to k - 1 do
    n := Scratch.push_ray w !n lo w.blob.found.(i) (-1) id o d
  done;
  !n

