(* The parametric surface: POV-Ray's shape/fpmetric.cpp, its operations in the same order. *)

type container = Box_container of Box.t | Sphere_container of { centre : Vec.t; radius : float }
type precomputed = { levels : int; low : float array array; high : float array array }

type t = {
  fx : Fn.t;
  fy : Fn.t;
  fz : Fn.t;
  umin : float;
  umax : float;
  vmin : float;
  vmax : float;
  accuracy : float;
  max_gradient : float;
  container : container;
  trans : Transform.t;
  precomputed : precomputed option;
  room : int;
}

let epsilon = Precision.epsilon

(* fpmetric.cpp's Max_intNumber: piece numbers stop doubling there *)
let max_piece = 10000000

(* pieces one search may test before povml stops it: a search with ranges far wider than its
   bounds can tell apart would otherwise halve them to the accuracy everywhere (2^depth pieces);
   the fidelity scenes never reach it *)
let max_pieces = 20_000

(* how many times the subdivision can halve [range] before it is below [accuracy] *)
let halvings range accuracy =
  let r = range /. accuracy in
  if not (Float.is_finite r) then 2048 else if r < 1. then 1 else min 2048 (int_of_float (Float.log2 r) + 2)

let make (fx, fy, fz) (u1, v1) (u2, v2) ~accuracy ~max_gradient container =
  let umin, umax = if u1 > u2 then (u2, u1) else (u1, u2) in
  let vmin, vmax = if v1 > v2 then (v2, v1) else (v1, v2) in
  let room = halvings (umax -. umin) accuracy + halvings (vmax -. vmin) accuracy + 8 in
  { fx; fy; fz; umin; umax; vmin; vmax; accuracy; max_gradient; container; trans = Transform.identity; precomputed = None; room }

let transform s m = { s with trans = Transform.compose s.trans m }

(* one frame that every function of the surface can run in: u and v in its x and y registers *)
let frame s = Array.make (max 3 (max s.fx.frame (max s.fy.frame s.fz.frame))) 0.

(* Evaluate_Function_UV: SetLocal of U and V, then the function *)
let[@inline] run (f : Fn.t) fr u v =
  fr.(0) <- u;
  fr.(1) <- v;
  f.eval fr

(* std::max and std::min as Parametric::Interval calls them *)
let[@inline] cmax (a : float) b = if a < b then b else a
let[@inline] cmin (a : float) b = if b < a then b else a

(* Parametric::Interval's offset: how far a function of gradient [mg] can stray beyond its
   values [a] and [b] at the ends of a span [dx] long *)
let[@inline] spread dx a b mg =
  let dy = Float.abs (a -. b) in
  let ofs = mg *. (dx -. (dy /. mg)) /. 2. in
  if ofs < 0. then 0. else ofs

(* Evaluate_Function_Interval_UV: bounds of [f] − [thr] over the piece [ulo, uhi] × [vlo, vhi]
   from its corners, left in iv.(0) (lower) and iv.(1) (upper) *)
let interval (f : Fn.t) fr thr ulo vlo uhi vhi mg (iv : float array) =
  let f00 = run f fr ulo vlo -. thr in
  let f01 = run f fr ulo vhi -. thr in
  let f10 = run f fr uhi vlo -. thr in
  let f11 = run f fr uhi vhi -. thr in
  let dv = vhi -. vlo and du = uhi -. ulo in
  let o0 = spread dv f00 f01 mg and o1 = spread dv f10 f11 mg in
  let f0min = cmin f00 f01 -. o0 and f0max = cmax f00 f01 +. o0 in
  let f1min = cmin f10 f11 -. o1 and f1max = cmax f10 f11 +. o1 in
  iv.(1) <- cmax f0max f1max +. spread du f0max f1max mg;
  iv.(0) <- cmin f0min f1min -. spread du f0min f1min mg

(* Precomp_Par_Int: piece [k] evaluated when it is of the last level, else its halves first (the
   longer side halved, u on a tie) and their bounds joined *)
let precompute s ~depth ~x ~y ~z =
  let chosen = [| x; y; z |] and fns = [| s.fx; s.fy; s.fz |] in
  let n = 1 lsl depth in
  let low = Array.map (fun c -> if c then Array.make n 0. else [||]) chosen in
  let high = Array.map (fun c -> if c then Array.make n 0. else [||]) chosen in
  let fr = frame s and iv = [| 0.; 0. |] and last = 1 lsl (depth - 1) in
  let rec piece k umin vmin umax vmax =
    if k >= last then
      for j = 0 to 2 do
        if chosen.(j) then begin
          interval fns.(j) fr s.accuracy umin vmin umax vmax s.max_gradient iv;
          low.(j).(k) <- iv.(0);
          high.(j).(k) <- iv.(1)
        end
      done
    else begin
      if umax -. umin < vmax -. vmin then begin
        let m = (vmin +. vmax) /. 2.0 in
        piece (2 * k) umin vmin umax m;
        piece ((2 * k) + 1) umin m umax vmax
      end
      else begin
        let m = (umin +. umax) /. 2.0 in
        piece (2 * k) umin vmin m vmax;
        piece ((2 * k) + 1) m vmin umax vmax
      end;
      for j = 0 to 2 do
        if chosen.(j) then begin
          let h = high.(j) and l = low.(j) in
          h.(k) <- (if h.(2 * k) > h.((2 * k) + 1) then h.(2 * k) else h.((2 * k) + 1));
          l.(k) <- (if l.(2 * k) < l.((2 * k) + 1) then l.(2 * k) else l.((2 * k) + 1))
        end
      done
    end
  in
  piece 1 s.umin s.vmin s.umax s.vmax;
  { s with precomputed = Some { levels = depth; low; high } }

(* Sphere::Intersect of the ray from [o] along the unit [d]: both crossings in span.(0), span.(1) *)
let sphere_crossings (c : Vec.t) r2 (o : Vec.t) (d : Vec.t) (span : float array) =
  let ocx = c.x -. o.x and ocy = c.y -. o.y and ocz = c.z -. o.z in
  let oc2 = (ocx *. ocx) +. (ocy *. ocy) +. (ocz *. ocz) in
  let tca = (ocx *. d.x) +. (ocy *. d.y) +. (ocz *. d.z) in
  if oc2 >= r2 && tca < epsilon then false
  else
    let h2 = r2 -. oc2 +. (tca *. tca) in
    if h2 > epsilon then begin
      let h = sqrt h2 in
      span.(0) <- tca -. h;
      span.(1) <- tca +. h;
      true
    end
    else false

(* The container's crossings (world depths) in span.(0), span.(1): the sphere meets the ray
   brought into parametric space and renormalised, its depths divided back; the box meets it
   unnormalised (Box::Intersect). POV-Ray then takes one sphere test back from the sphere's
   counters, which it never counted. *)
let container_crossings (w : Scratch.t) s (p : Vec.t) (q : Vec.t) span =
  match s.container with
  | Sphere_container { centre; radius } ->
      let len = sqrt ((q.x *. q.x) +. (q.y *. q.y) +. (q.z *. q.z)) in
      let k = 1.0 /. len in
      let hit = sphere_crossings centre (radius *. radius) p (Vec.make (q.x *. k) (q.y *. k) (q.z *. k)) span in
      let st = w.stats in
      Stats.untest st Stats.sphere;
      if hit then begin
        Stats.unhit st Stats.sphere;
        span.(0) <- span.(0) /. len;
        span.(1) <- span.(1) /. len
      end;
      hit
  | Box_container b ->
      Box.crossed w b p.x p.y p.z q.x q.y q.z
      && begin
           span.(0) <- w.slab.t_near;
           span.(1) <- w.slab.t_far;
           true
         end

(* The depths of one search, all floats (stored flat): the ray's ranges through the x and y slabs
   of the piece being tested, the near depth of the last slab crossed (TPotRes), the longest range
   (TLen), the container's span [d1, d2] and the nearest crossing so far; and the piece, (u, v)
   from (ulo, vlo) to (uhi, vhi). *)
type depths = {
  mutable xmin : float;
  mutable xmax : float;
  mutable ymin : float;
  mutable ymax : float;
  mutable tpot : float;
  mutable tlen : float;
  d1 : float;
  d2 : float;
  mutable best : float;
  mutable ulo : float;
  mutable vlo : float;
  mutable uhi : float;
  mutable vhi : float;
}

(* whether the ray runs parallel to the x or y slabs of the piece being tested *)
type parallel = { mutable par_x : bool; mutable par_y : bool }

(* what one search works with: the surface, a frame for its functions, room for one function's
   bounds, the depths, and the piece numbers below which each function's bounds are precomputed *)
type walk = { surf : t; fr : float array; iv : float array; dp : depths; par : parallel; limits : int array }

(* One axis (0, 1, 2) of the piece, bounded by [low, high] on it, for the ray at [pa] along [qa]
   on that axis: whether the piece survives *)
let axis (dp : depths) par a low high pa qa =
  if Float.abs qa < epsilon then begin
    if a = 0 then par.par_x <- true else if a = 1 then par.par_y <- true;
    not (high < pa || low > pa)
  end
  else begin
    let t1 = (high -. pa) /. qa and t2 = (low -. pa) /. qa in
    let tmin = if t1 > t2 then t2 else t1 and tmax = if t1 > t2 then t1 else t2 in
    if tmin > dp.d2 || tmax < dp.d1 then false
    else begin
      dp.tpot <- tmin;
      if tmin > dp.best then false
      else if a > 0 && (not par.par_x) && (tmin > dp.xmax || tmax < dp.xmin) then false
      else if a > 1 && (not par.par_y) && (tmin > dp.ymax || tmax < dp.ymin) then false
      else begin
        if a = 0 then begin
          dp.xmin <- tmin;
          dp.xmax <- tmax;
          dp.tlen <- tmax -. tmin
        end
        else begin
          if a = 1 then begin
            dp.ymin <- tmin;
            dp.ymax <- tmax
          end;
          if tmax -. tmin > dp.tlen then dp.tlen <- tmax -. tmin
        end;
        true
      end
    end
  end

(* The bounds of function [j] over the piece numbered [num], left in wk.iv: precomputed for the
   numbers below its limit (and above 0), else evaluated *)
let piece_bounds wk j num =
  let s = wk.surf and dp = wk.dp in
  match s.precomputed with
  | Some p when num < wk.limits.(j) && num > 0 ->
      wk.iv.(0) <- p.low.(j).(num);
      wk.iv.(1) <- p.high.(j).(num)
  | Some _ | None ->
      let f = if j = 0 then s.fx else if j = 1 then s.fy else s.fz in
      interval f wk.fr s.accuracy dp.ulo dp.vlo dp.uhi dp.vhi s.max_gradient wk.iv

(* whether the ray from [p] along [q] (parametric space) passes through the x, y and z bounds
   of the piece numbered [num], each tried only if the one before let it through *)
let survives wk num (p : Vec.t) (q : Vec.t) =
  let dp = wk.dp and par = wk.par in
  par.par_x <- false;
  par.par_y <- false;
  dp.tlen <- 0.;
  piece_bounds wk 0 num;
  axis dp par 0 wk.iv.(0) wk.iv.(1) p.x q.x
  && begin
       piece_bounds wk 1 num;
       axis dp par 1 wk.iv.(0) wk.iv.(1) p.y q.y
     end
  && begin
       piece_bounds wk 2 num;
       axis dp par 2 wk.iv.(0) wk.iv.(1) p.z q.z
     end

let limits s =
  match s.precomputed with
  | Some pc -> Array.map (fun l -> if Array.length l > 0 then 1 lsl pc.levels else 0) pc.low
  | None -> [| 0; 0; 0 |]

(* The subdivision: a stack of pieces, the current one on top; a piece the ray passes through is
   a crossing when it is smaller than the accuracy (in u and v, or in the depths it spans), else
   it is halved along its longer side, the lower half pushed on top (numbered 2k), the upper
   half kept below it (2k + 1). The nearest crossing's (u, v) is left in uv. *)
let subdivide (w : Scratch.t) wk (p : Vec.t) (q : Vec.t) (uv : float array) =
  let s = wk.surf and dp = wk.dp and n = wk.surf.room in
  let budget = ref max_pieces in
  let lu = Array.make n 0. and hu = Array.make n 0. and lv = Array.make n 0. and hv = Array.make n 0. in
  let piece = Array.make n 0 in
  lu.(0) <- s.umin;
  hu.(0) <- s.umax;
  lv.(0) <- s.vmin;
  hv.(0) <- s.vmax;
  piece.(0) <- 1;
  let i = ref 0 in
  while !i >= 0 do
    decr budget;
    if !budget = 0 then begin
      (* povml's limit: a search that has tested this many pieces stops with what it found *)
      Stats.test w.stats Stats.parametric_cut;
      i := 0
    end;
    if !budget <= 0 then decr i
    else
    let k = !i in
    let ulo = lu.(k) and uhi = hu.(k) and vlo = lv.(k) and vhi = hv.(k) and num = piece.(k) in
    dp.ulo <- ulo;
    dp.uhi <- uhi;
    dp.vlo <- vlo;
    dp.vhi <- vhi;
    let split_v = vhi -. vlo > uhi -. ulo in
    if not (survives wk num p q) then decr i
    else begin
      let len = if split_v then vhi -. vlo else uhi -. ulo in
      let len = if len > dp.tlen then dp.tlen else len in
      (* POV-Ray's stack has room for 32 pieces; this one for every halving its bounds allow *)
      if len < s.accuracy || k + 1 >= n then begin
        if dp.best > dp.tpot && dp.tpot > dp.d1 then begin
          dp.best <- dp.tpot;
          uv.(0) <- ulo;
          uv.(1) <- vlo
        end;
        decr i
      end
      else begin
        let twice = if 2 * num >= max_piece then max_piece else 2 * num in
        piece.(k + 1) <- twice;
        piece.(k) <- twice + 1;
        lu.(k + 1) <- ulo;
        hu.(k + 1) <- uhi;
        lv.(k + 1) <- vlo;
        hv.(k + 1) <- vhi;
        if split_v then begin
          let m = (vhi +. vlo) /. 2.0 in
          hv.(k + 1) <- m;
          lv.(k) <- m
        end
        else begin
          let m = (uhi +. ulo) /. 2.0 in
          hu.(k + 1) <- m;
          lu.(k) <- m
        end;
        i := k + 1
      end
    end
  done

(* Parametric::All_Intersections: the nearest crossing's world depth (infinity when none is
   before the container's far side), its (u, v) left in uv.(0), uv.(1) *)
let search (w : Scratch.t) s (o : Vec.t) (d : Vec.t) (uv : float array) =
  let st = w.stats in
  Stats.test st Stats.parametric_bound;
  let p = Transform.inv_point s.trans o and q = Transform.inv_direction s.trans d in
  let span = [| 0.; 0. |] in
  if not (container_crossings w s p q span) then infinity
  else begin
    Stats.hit st Stats.parametric_bound;
    Stats.test st Stats.parametric;
    let d2 = span.(1) in
    let d1 = (if span.(0) = d2 then 0. else span.(0)) +. (4. *. s.accuracy) in
    if d1 > d2 then infinity
    else begin
      let dp = { xmin = 0.; xmax = 0.; ymin = 0.; ymax = 0.; tpot = 0.; tlen = 0.; d1; d2; best = infinity; ulo = 0.; vlo = 0.; uhi = 0.; vhi = 0. } in
      let wk = { surf = s; fr = frame s; iv = [| 0.; 0. |]; dp; par = { par_x = false; par_y = false }; limits = limits s } in
      subdivide w wk p q uv;
      if dp.best < d2 then begin
        Stats.hit st Stats.parametric;
        dp.best
      end
      else infinity
    end
  end

(* the crossing, its report left in [w.crossing] *)
let found (w : Scratch.t) s o d =
  let uv = [| 0.; 0. |] in
  let t = search w s o d uv in
  if t < infinity then Crossing.set w.crossing (Vec.madd o t d) Vec.zero uv.(0) uv.(1);
  t

let depth (w : Scratch.t) s o d lo =
  let t = found w s o d in
  if t >= lo then begin
    w.reported <- true;
    t
  end
  else infinity

let hits w s id o d lo n =
  let t = found w s o d in
  if t < infinity && t >= lo then Scratch.push_reported w n t id else n

let normal_at s u v =
  let fr = frame s in
  let fx0 = run s.fx fr u v and fy0 = run s.fy fr u v and fz0 = run s.fz fr u v in
  let u1 = u +. s.accuracy in
  let ru = Vec.make (-.fx0 +. run s.fx fr u1 v) (-.fy0 +. run s.fy fr u1 v) (-.fz0 +. run s.fz fr u1 v) in
  let v1 = v +. s.accuracy in
  let rv = Vec.make (-.fx0 +. run s.fx fr u v1) (-.fy0 +. run s.fy fr u v1) (-.fz0 +. run s.fz fr u v1) in
  Transform.normalize (Transform.normal s.trans (Vec.cross ru rv))

let hit_normal s c = normal_at s (Crossing.u c) (Crossing.v c)

let box s =
  match s.container with
  | Box_container b -> [| b.x0; b.y0; b.z0; b.x1; b.y1; b.z1 |]
  | Sphere_container { centre = c; radius = r } -> [| c.x -. r; c.y -. r; c.z -. r; c.x +. r; c.y +. r; c.z +. r |]

let bounds s = Transform.bounds s.trans (box s)

let pov_box s =
  let f32 = Precision.f32 in
  let b =
    match s.container with
    | Box_container b -> [| f32 b.x0; f32 b.y0; f32 b.z0; f32 (b.x1 -. b.x0); f32 (b.y1 -. b.y0); f32 (b.z1 -. b.z0) |]
    | Sphere_container { centre = c; radius = r } -> [| f32 (c.x -. r); f32 (c.y -. r); f32 (c.z -. r); f32 (r *. 2.); f32 (r *. 2.); f32 (r *. 2.) |]
  in
  Pov_box.mapped s.trans b

let traits = { Traits.default with name = "parametric"; inverse_flag = false; patch = true }
