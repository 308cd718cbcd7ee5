(* The isosurface: POV-Ray's shape/isosurf.cpp, its root search and its per-thread cache. *)

type container = Box_container of { lo : Vec.t; hi : Vec.t } | Sphere_container of { centre : Vec.t; radius : float }
type evaluate = { p0 : float; p1 : float; p2 : float }

type t = {
  fn : Fn.t;
  container : container;
  threshold : float;
  accuracy : float;
  max_gradient : float;
  max_trace : int;
  closed : bool;
  evaluate : evaluate option;
  trans : Transform.t;
  key : int;
  copy : bool;
}

type compiled = { iso : t; slot : int; box : float array }

let accuracy_default = 0.001
let max_gradient_default = 1.1
let max_trace_limit = 10

(* BOUND_HUGE: a depth no search goes beyond *)
let bound_huge = 2e10
let epsilon = Precision.epsilon

let make ~fn ~key =
  {
    fn;
    container = Box_container { lo = Vec.make (-1.) (-1.) (-1.); hi = Vec.make 1. 1. 1. };
    threshold = 0.;
    accuracy = accuracy_default;
    max_gradient = max_gradient_default;
    max_trace = 1;
    closed = true;
    evaluate = None;
    trans = Transform.identity;
    key;
    copy = false;
  }

let transform s m = { s with trans = Transform.compose s.trans m }
let mark_copy s = { s with copy = true }

(* std::min and std::max as <algorithm> has them: the first argument unless the second is
   strictly smaller (larger) *)
let[@inline] std_min (a : float) b = if b < a then b else a
let[@inline] std_max (a : float) b = if a < b then b else a

(* Evaluate_Function: the function at a point of the isosurface's space, in the frame [fr] (the
   point in its first three cells; the rest are the function's own: parameters beyond x, y, z,
   which stay 0, and counters, which it sets before it reads them) *)
let[@inline] value_in fr c x y z =
  fr.(0) <- x;
  fr.(1) <- y;
  fr.(2) <- z;
  c.iso.fn.eval fr

(* the same in a frame of its own (Normal and Inside, which may run outside a search) *)
let value c x y z = Fn.at_point c.iso.fn x y z

(* Vector_Function: the function less the threshold at P + t·D (VEvaluateRay), in the search's frame *)
let[@inline] level c (r : Scratch.iso_search) t =
  value_in r.frame c (r.px +. (t *. r.dx)) (r.py +. (t *. r.dy)) (r.pz +. (t *. r.dz)) -. c.iso.threshold

(* Float_Function: the same, times the sign of the search *)
let[@inline] along c (r : Scratch.iso_search) t = r.inv3 *. level c r t

(* ---------------------------------------------------------------------------------------------- *)
(* The root search (Function_Find_Root and Function_Find_Root_R) *)

(* Function_Find_Root_R over [t1, t2] (values f1, f2): no root is possible where f1 + f2 is at
   least the gradient bound [dt] of the interval; otherwise it is halved, the near half first,
   down to the accuracy, where a negative far end is the root. [len] is 1 / (|D|·(t2 − t1)),
   for the gradient the interval shows; [g] is where this isosurface's findings are counted. *)
let rec root_r c (w : Scratch.t) (r : Scratch.iso_search) g t1 f1 t2 f2 dt t21 len =
  let temp = Float.abs ((f2 -. f1) *. len) in
  let found = w.stats.iso_found in
  if found.(g) < temp then found.(g) <- temp;
  let dt =
    match c.iso.evaluate with
    | Some e when r.maxg < temp *. e.p1 ->
        r.maxg <- temp *. e.p1 *. e.p1;
        r.maxg *. r.vlength *. t21
    | Some _ | None -> dt
  in
  if t21 < c.iso.accuracy then
    if f2 < 0. then begin
      r.tl <- t2;
      true
    end
    else false
  else if f1 +. f2 -. dt < 0. then begin
    let t21 = t21 *. 0.5 and dt = dt *. 0.5 in
    let ta = t1 +. t21 in
    let fa = along c r ta in
    r.fmax <- std_min fa r.fmax;
    root_r c w r g t1 f1 ta fa dt t21 (len *. 2.0) || root_r c w r g ta fa t2 f2 dt t21 (len *. 2.0)
  end
  else false

(* the distance from P + t·D to (x, y, z) *)
let[@inline] gap (r : Scratch.iso_search) t x y z =
  let vx = r.px +. (t *. r.dx) -. x and vy = r.py +. (t *. r.dy) -. y and vz = r.pz +. (t *. r.dz) -. z in
  sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz))

(* The cache: the last search of this isosurface found no root on a segment whose least value
   seen exceeds max_gradient times how far this segment's ends are from that one's *)
let cached_miss c (w : Scratch.t) t1 t2 =
  let room = w.iso and r = w.iso.at in
  room.cached && room.owner = c.slot
  && begin
       let st = w.stats in
       Stats.test st Stats.isosurface_cache;
       let l_b = gap r t1 r.bx r.by r.bz and l_e = gap r t2 r.ex r.ey r.ez in
       r.fmax -. (r.maxg *. std_max l_b l_e) > 0.
       && begin
            Stats.hit st Stats.isosurface_cache;
            true
          end
     end

(* what [evaluate] keeps of a search that found a root (ISO_Max_Gradient) *)
let count_evaluated (w : Scratch.t) g maxg oldmg =
  let found = w.stats.iso_found in
  let curvar = Float.abs (maxg -. oldmg) in
  if curvar > found.(g + 4) then found.(g + 4) <- curvar;
  found.(g + 2) <- found.(g + 2) +. 1.;
  found.(g + 3) <- found.(g + 3) +. maxg;
  if maxg > found.(g + 1) then found.(g + 1) <- maxg

(* Function_Find_Root over [t1, t2] of the ray in [w.iso.at]: the root in [r.tl] *)
let find_root c (w : Scratch.t) g t1 t2 =
  let r = w.iso.at and iso = c.iso in
  Stats.test w.stats Stats.isosurface_roots;
  r.vlength <- sqrt ((r.dx *. r.dx) +. (r.dy *. r.dy) +. (r.dz *. r.dz));
  if cached_miss c w t1 t2 then false
  else begin
    w.iso.cached <- false;
    let f1 = along c r t1 in
    r.fmax <- f1;
    let f1 =
      if (not iso.closed) && f1 < 0. then begin
        r.inv3 <- -.r.inv3;
        -.f1
      end
      else f1
    in
    let f2 = along c r t2 in
    r.fmax <- std_min f2 r.fmax;
    let oldmg = r.maxg and t21 = t2 -. t1 in
    (match iso.evaluate with Some e when oldmg > e.p0 -> r.maxg <- oldmg *. e.p2 | Some _ | None -> ());
    let dt = r.maxg *. r.vlength *. t21 in
    if root_r c w r g t1 f1 t2 f2 dt t21 (1.0 /. (r.vlength *. t21)) then begin
      if iso.evaluate <> None then count_evaluated w g r.maxg oldmg;
      true
    end
    else begin
      if not w.shadow_ray then begin
        (* the segment's ends kept for the next search *)
        let room = w.iso in
        room.cached <- true;
        room.owner <- c.slot;
        r.bx <- r.px +. (t1 *. r.dx);
        r.by <- r.py +. (t1 *. r.dy);
        r.bz <- r.pz +. (t1 *. r.dz);
        r.ex <- r.px +. (t2 *. r.dx);
        r.ey <- r.py +. (t2 *. r.dy);
        r.ez <- r.pz +. (t2 *. r.dz)
      end;
      false
    end
  end

(* ---------------------------------------------------------------------------------------------- *)
(* All_Intersections *)

(* Sphere::Intersect of the unit ray from [p] along [u] (the static test, uncounted), its depths
   left in [w.slab] *)
let sphere_crossed (w : Scratch.t) (centre : Vec.t) r2 (p : Vec.t) (u : Vec.t) =
  let ox = centre.x -. p.x and oy = centre.y -. p.y and oz = centre.z -. p.z in
  let oc2 = (ox *. ox) +. (oy *. oy) +. (oz *. oz) in
  let tca = (ox *. u.x) +. (oy *. u.y) +. (oz *. u.z) in
  if oc2 >= r2 && tca < epsilon then false
  else
    let thc2 = r2 -. oc2 +. (tca *. tca) in
    thc2 > epsilon
    && begin
         let hc = sqrt thc2 in
         w.slab.t_near <- tca -. hc;
         w.slab.t_far <- tca +. hc;
         true
       end

(* The container crossed by the ray from [p] along [v] (isosurface space, [v] not renormalised):
   whether it is, the depths in [w.slab] and the sides in [w.side_near], [w.side_far]. A
   sphere container is met by the renormalised ray, its depths scaled back; POV-Ray takes the
   test off the sphere counters (which it never added to). *)
let container_crossed c (w : Scratch.t) (p : Vec.t) (v : Vec.t) =
  match c.iso.container with
  | Box_container { lo; hi } -> Box.crossed w (Box.make lo hi) p.x p.y p.z v.x v.y v.z
  | Sphere_container { centre; radius } ->
      let len = sqrt ((v.x *. v.x) +. (v.y *. v.y) +. (v.z *. v.z)) in
      let k = 1.0 /. len in
      let met = sphere_crossed w centre (radius *. radius) p (Vec.make (v.x *. k) (v.y *. k) (v.z *. k)) in
      w.side_near <- 0;
      w.side_far <- 0;
      let st = w.stats in
      Stats.untest st Stats.sphere;
      if met then begin
        Stats.unhit st Stats.sphere;
        w.slab.t_near <- w.slab.t_near /. len;
        w.slab.t_far <- w.slab.t_far /. len
      end;
      met

(* one crossing found: its depth and side in [w.iso_hits] *)
let[@inline] found (w : Scratch.t) n t side =
  w.iso_hits.(2 * n) <- t;
  w.iso_hits.((2 * n) + 1) <- float_of_int side;
  n + 1

(* A closed isosurface's container surface: where the ray enters it with the function negative
   there, the entry is a crossing and the search starts inside (the sign turned); a ray starting
   inside the container (or closer than the accuracy to it) starts its search past 5·accuracy
   when the function is nearly 0 at its start, and its exit is a crossing where the function is
   negative. The count of crossings, of the crossings searched, and the start of the search. *)
let container_surface c (w : Scratch.t) t1 t2 =
  let r = w.iso.at and acc = c.iso.accuracy in
  let tmp = level c r t1 in
  if t1 > acc then
    if tmp < 0. then begin
      r.inv3 <- -.r.inv3;
      (found w 0 t1 w.side_near, 1, t1)
    end
    else (0, 0, t1)
  else
    let t1 =
      if tmp < r.maxg *. acc *. 4.0 then begin
        let t1 = acc *. 5.0 in
        if level c r t1 < 0. then r.inv3 <- -1.;
        t1
      end
      else t1
    in
    if level c r t2 < 0. then (found w 0 t2 w.side_far, 0, t1) else (0, 0, t1)

(* The roots along the ray: up to max_trace of them (with the container's crossing), each
   search starting 5·accuracy past the last root with the sign turned. *)
let roots c (w : Scratch.t) g n itrace tmin tmax =
  let r = w.iso.at and acc = c.iso.accuracy in
  let rec next n itrace tmin =
    if itrace >= c.iso.max_trace || not (find_root c w g tmin tmax) then n
    else
      let n = found w n r.tl 0 in
      let tmin = r.tl +. (acc *. 5.0) in
      if tmax -. tmin < acc then n
      else begin
        r.inv3 <- -.r.inv3;
        next n (itrace + 1) tmin
      end
  in
  next n itrace tmin

(* The search of the ray inside the container crossed at [t1, t2]: the crossings found *)
let search_inside c (w : Scratch.t) g t1 t2 =
  let r = w.iso.at and acc = c.iso.accuracy and st = w.stats in
  r.inv3 <- 1.;
  let n, itrace, t1 = if c.iso.closed then container_surface c w t1 t2 else (0, 0, t1) in
  let tmax = std_min t2 bound_huge in
  let tmin = std_min tmax t1 in
  if tmax -. tmin < acc then 0 (* the container's crossing too is dropped *)
  else begin
    Stats.test st Stats.isosurface;
    let tmin =
      if tmin < acc && r.inv3 = 1. && Float.abs (level c r tmin) < r.maxg *. acc *. 4.0 then begin
        (* the ray starts on the surface: the search starts past it, inside if it goes in *)
        let t = acc *. 5.0 in
        if level c r t < 0. then r.inv3 <- -1.;
        t
      end
      else tmin
    in
    let n = roots c w g n itrace tmin tmax in
    if n > 0 then Stats.hit st Stats.isosurface;
    n
  end

(* What the worker keeps for the isosurface [c], made when it first searches it *)
let own (w : Scratch.t) c : Scratch.iso_own =
  let room = w.iso in
  let k = c.slot in
  match if k < Array.length room.own then room.own.(k) else None with
  | Some own -> own
  | None ->
      let own = { Scratch.frame = Fn.frame c.iso.fn; grad_used = c.iso.max_gradient } in
      if k >= Array.length room.own then begin
        let bigger = Array.make (max (k + 1) (2 * Array.length room.own)) None in
        Array.blit room.own 0 bigger 0 (Array.length room.own);
        room.own <- bigger
      end;
      room.own.(k) <- Some own;
      own

(* All_Intersections of the world ray from [o] along [d]: the crossings in [w.iso_hits], their
   count returned *)
let search c (w : Scratch.t) (o : Vec.t) (d : Vec.t) =
  let st = w.stats and tr = c.iso.trans in
  Stats.test st Stats.isosurface_container;
  let g = Stats.iso_slot st c.iso.key in
  let p = Transform.inv_point tr o and v = Transform.inv_direction tr d in
  let r = w.iso.at and own = own w c in
  r.frame <- own.frame;
  r.maxg <- own.grad_used;
  let n =
    if not (container_crossed c w p v) then 0
    else begin
      Stats.hit st Stats.isosurface_container;
      let t1 = if w.slab.t_near < 0. then 0. else w.slab.t_near in
      r.px <- p.x;
      r.py <- p.y;
      r.pz <- p.z;
      r.dx <- v.x;
      r.dy <- v.y;
      r.dz <- v.z;
      search_inside c w g t1 w.slab.t_far
    end
  in
  if c.iso.evaluate <> None then own.grad_used <- std_max own.grad_used r.maxg;
  n

let depth w c o d lo =
  let n = search c w o d in
  let best = ref infinity and side = ref 0 in
  for i = n - 1 downto 0 do
    let t = w.iso_hits.(2 * i) in
    if t < !best && t >= lo then begin
      best := t;
      side := int_of_float w.iso_hits.((2 * i) + 1)
    end
  done;
  if !best < infinity then w.part <- !side;
  !best

let hits w c id o d lo n =
  let k = search c w o d in
  let n = ref n in
  for i = 0 to k - 1 do
    n := Scratch.push_ray w !n lo w.iso_hits.(2 * i) (int_of_float w.iso_hits.((2 * i) + 1)) id o d
  done;
  !n

(* ---------------------------------------------------------------------------------------------- *)
(* Normal, inside, boxes *)

let gradient c (q : Vec.t) =
  let acc = c.iso.accuracy in
  let f0 = value c q.x q.y q.z in
  let nx = value c (q.x +. acc) q.y q.z -. f0 in
  let ny = value c q.x (q.y +. acc) q.z -. f0 in
  let nz = value c q.x q.y (q.z +. acc) -. f0 in
  let nx = if nx = 0. && ny = 0. && nz = 0. then 1. else nx in
  Vec.normalize (Vec.make nx ny nz)

let normal c side (p : Vec.t) =
  let tr = c.iso.trans in
  let n =
    if side >= 1 && side <= 6 then Box.side_normal side
    else
      let q = Transform.inv_point tr p in
      match c.iso.container with
      | Sphere_container { centre; radius } ->
          let rv = Vec.sub q centre in
          if Float.abs (Vec.length rv -. radius) < epsilon then Vec.scale (1.0 /. radius) rv else gradient c q
      | Box_container _ -> gradient c q
  in
  Transform.normalize (Transform.normal tr n)

let inside c (p : Vec.t) =
  let q = Transform.inv_point c.iso.trans p in
  let within =
    match c.iso.container with
    | Sphere_container { centre; radius } ->
        let oc = Vec.sub centre q in
        not (Vec.dot oc oc > radius *. radius)
    | Box_container { lo; hi } -> not (q.x < lo.x || q.x > hi.x || q.y < lo.y || q.y > hi.y || q.z < lo.z || q.z > hi.z)
  in
  within && not (value c q.x q.y q.z -. c.iso.threshold > 0.)

let corners s =
  match s.container with
  | Box_container { lo; hi } -> (lo, hi)
  | Sphere_container { centre = cn; radius = r } -> (Vec.make (cn.x -. r) (cn.y -. r) (cn.z -. r), Vec.make (cn.x +. r) (cn.y +. r) (cn.z +. r))

let bounds s =
  let lo, hi = corners s in
  Transform.bounds s.trans [| lo.x; lo.y; lo.z; hi.x; hi.y; hi.z |]

let pov_box s =
  let f = Precision.f32 in
  let b =
    match s.container with
    | Box_container { lo; hi } -> [| f lo.x; f lo.y; f lo.z; f (hi.x -. lo.x); f (hi.y -. lo.y); f (hi.z -. lo.z) |]
    | Sphere_container { centre = cn; radius = r } ->
        [| f (cn.x -. r); f (cn.y -. r); f (cn.z -. r); f (r *. 2.); f (r *. 2.); f (r *. 2.) |]
  in
  Pov_box.mapped s.trans b

let compile ~slot s = { iso = s; slot; box = pov_box s }

(* ---------------------------------------------------------------------------------------------- *)
(* What POV-Ray says at the end of the render (DispatchShutdownMessages) *)

let warning s (stats : Stats.t) =
  let g = s.key * Stats.iso_width in
  let get i = if g + i < Array.length stats.iso_found then stats.iso_found.(g + i) else 0. in
  let f v = Precision.f32 v in
  match s.evaluate with
  | None ->
      let found = get 0 and mg = s.max_gradient in
      if not (found > epsilon && mg > epsilon) then None
      else
        let diff = mg -. found and prop = Float.abs (mg /. found) in
        if (prop <= 0.9 && diff <= -0.5) || ((prop <= 0.95 || diff <= -0.1) && mg < 10.0) then
          Some
            (Printf.sprintf
               "The maximum gradient found was %0.3f, but max_gradient of the isosurface was set to %0.3f. The isosurface may \
                contain holes! Adjust max_gradient to get a proper rendering of the isosurface."
               (f found) (f mg))
        else if diff >= 10.0 || (prop >= 1.1 && diff >= 0.5) then
          Some
            (Printf.sprintf
               "The maximum gradient found was %0.3f, but max_gradient of the isosurface was set to %0.3f. Adjust max_gradient \
                to get a faster rendering of the isosurface."
               (f found) (f mg))
        else None
  | Some e ->
      let eval_max = get 1 and cnt = get 2 and sum = get 3 and var = get 4 in
      let diff = eval_max /. std_max (eval_max -. var) epsilon in
      if e.p0 > eval_max || e.p1 > diff then
        let cnt = std_max cnt 1.0 in
        Some
          (Printf.sprintf
             "Evaluate found a maximum gradient of %0.3f and an average gradient of %0.3f. The maximum gradient variation was %0.3f."
             (f eval_max) (f (sum /. cnt)) (f var))
      else None

let traits = { Traits.default with name = "isosurface" }
