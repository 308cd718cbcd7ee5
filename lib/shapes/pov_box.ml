(* POV-Ray's single-precision bounding boxes: how they are made, entered by a ray, and tested. *)

let f32 = Precision.f32
let epsilon = Precision.epsilon

let of_min_max (lo : float array) (hi : float array) = Array.init 6 (fun i -> if i < 3 then f32 lo.(i) else f32 (hi.(i - 3) -. lo.(i - 3)))

(* BOUNDS_VOLUME: the product of the single-precision lengths, taken in single precision *)
let volume (b : float array) = f32 (f32 (b.(3) *. b.(4)) *. b.(5))

(* Post_Process: INFINITE_VOLUME is BOUND_HUGE *)
let infinite b = Array.length b = 0 || volume b > 2e10

let mapped tr b =
  let lo = [| b.(0); b.(1); b.(2) |] and hi = [| b.(0) +. b.(3); b.(1) +. b.(4); b.(2) +. b.(5) |] in
  let m = Transform.bounds tr (Array.append lo hi) in
  of_min_max (Array.sub m 0 3) (Array.sub m 3 3)

(* The depth where the ray from [o] along [d] enters the box [b] (POV-Ray's Intersect_BBox), or
   infinity: the X slab's interval, narrowed by the Y and Z slabs in single precision. Written
   without closures, options or tuples, so that it allocates nothing. *)
let entry (b : float array) (o : Vec.t) (d : Vec.t) =
  let bound_huge = 2e10 in
  let miss = ref false and dmin = ref (-.bound_huge) and dmax = ref bound_huge in
  (* the X slab: its interval along the ray, or the whole ray for a direction parallel to it *)
  let dn = d.x in
  if dn <> 0. then begin
    let sd = f32 (1. /. dn) in
    let near = f32 (f32 (b.(0) -. f32 o.x) *. sd) in
    let span = f32 (b.(3) *. sd) in
    let lo = if dn > 0. then near else near +. span and hi = if dn > 0. then near +. span else near in
    if hi < epsilon || lo > hi then miss := true
    else begin
      dmin := lo;
      dmax := hi
    end
  end
  else begin
    let sn = f32 o.x in
    if sn < b.(0) || sn > f32 (b.(3) +. b.(0)) then miss := true
  end;
  (* the Y slab narrows the interval *)
  (if not !miss then
     let dn = d.y in
     if dn <> 0. then begin
       let sd = f32 (1. /. dn) in
       let near = f32 (f32 (b.(1) -. f32 o.y) *. sd) in
       let span = f32 (b.(4) *. sd) in
       let tmin = if dn > 0. then near else near +. span and tmax = if dn > 0. then near +. span else near in
       if tmax < !dmax then begin
         if tmax < epsilon then miss := true
         else if tmin > !dmin then (if tmin > tmax then miss := true else dmin := tmin)
         else if !dmin > tmax then miss := true;
         dmax := tmax
       end
       else if tmin > !dmin then if tmin > !dmax then miss := true else dmin := tmin
     end
     else
       let sn = f32 o.y in
       if sn < b.(1) || sn > f32 (b.(4) +. b.(1)) then miss := true);
  (* the Z slab: only the entry is used afterwards, so dmax is not lowered *)
  (if not !miss then
     let dn = d.z in
     if dn <> 0. then begin
       let sd = f32 (1. /. dn) in
       let near = f32 (f32 (b.(2) -. f32 o.z) *. sd) in
       let span = f32 (b.(5) *. sd) in
       let tmin = if dn > 0. then near else near +. span and tmax = if dn > 0. then near +. span else near in
       if tmax < !dmax then begin
         if tmax < epsilon then miss := true
         else if tmin > !dmin then if tmin > tmax then miss := true else dmin := tmin
         else if !dmin > tmax then miss := true
       end
       else if tmin > !dmin then if tmin > !dmax then miss := true else dmin := tmin
     end
     else
       let sn = f32 o.z in
       if sn < b.(2) || sn > f32 (b.(5) +. b.(2)) then miss := true);
  if !miss then infinity else !dmin

(* The same entry with the ray's Rayinfo computed once: per axis whether the direction is not 0,
   the origin in single precision and the reciprocal direction in single precision. *)
type ray_info = {
  ri : float array;  (** x, y, z: origin (0–2), reciprocal direction (3–5); 6–7: dmin, dmax *)
  mutable nonzero : int;  (** bit k: the direction's axis k is not 0 *)
  mutable positive : int;  (** bit k: it is positive *)
}

let ray_info () = { ri = Array.make 8 0.; nonzero = 0; positive = 0 }

let set_ray i (o : Vec.t) (d : Vec.t) =
  let r = i.ri in
  r.(0) <- f32 o.x;
  r.(1) <- f32 o.y;
  r.(2) <- f32 o.z;
  let axis k dn =
    if dn <> 0. then begin
      r.(3 + k) <- f32 (1. /. dn);
      i.nonzero <- i.nonzero lor (1 lsl k);
      if dn > 0. then i.positive <- i.positive lor (1 lsl k)
    end
  in
  i.nonzero <- 0;
  i.positive <- 0;
  axis 0 d.x;
  axis 1 d.y;
  axis 2 d.z

(* one of the Y and Z slabs narrowing [dmin, dmax] (kept in ri.(6), ri.(7)); false on a miss *)
let[@inline] narrow i (b : float array) k ~last =
  let r = i.ri in
  let ll = b.(k) and len = b.(k + 3) and sn = r.(k) in
  if i.nonzero land (1 lsl k) <> 0 then begin
    let sd = r.(3 + k) in
    let near = f32 (f32 (ll -. sn) *. sd) in
    let span = f32 (len *. sd) in
    let pos = i.positive land (1 lsl k) <> 0 in
    let tmin = if pos then near else near +. span and tmax = if pos then near +. span else near in
    let dmin = r.(6) and dmax = r.(7) in
    if tmax < dmax then begin
      if tmax < epsilon then false
      else if tmin > dmin then
        if tmin > tmax then false
        else begin
          r.(6) <- tmin;
          if not last then r.(7) <- tmax;
          true
        end
      else if dmin > tmax then false
      else begin
        if not last then r.(7) <- tmax;
        true
      end
    end
    else if tmin > dmin then
      if tmin > dmax then false
      else begin
        r.(6) <- tmin;
        true
      end
    else true
  end
  else not (sn < ll || sn > f32 (len +. ll))

let entry_from i (b : float array) =
  let r = i.ri in
  let x_ok =
    if i.nonzero land 1 <> 0 then begin
      let sd = r.(3) in
      let near = f32 (f32 (b.(0) -. r.(0)) *. sd) in
      let span = f32 (b.(3) *. sd) in
      let pos = i.positive land 1 <> 0 in
      let lo = if pos then near else near +. span and hi = if pos then near +. span else near in
      if hi < epsilon || lo > hi then false
      else begin
        r.(6) <- lo;
        r.(7) <- hi;
        true
      end
    end
    else begin
      let sn = r.(0) in
      r.(6) <- -2e10;
      r.(7) <- 2e10;
      not (sn < b.(0) || sn > f32 (b.(3) +. b.(0)))
    end
  in
  if x_ok && narrow i b 1 ~last:false && narrow i b 2 ~last:true then r.(6) else infinity

let contains (b : float array) (p : Vec.t) =
  Array.length b = 0
  || not
       (p.x < b.(0) || p.y < b.(1) || p.z < b.(2) || p.x > b.(0) +. b.(3) || p.y > b.(1) +. b.(4) || p.z > b.(2) +. b.(5))

(* Intersect_BBox_Dir with FindIntersection's arguments: the origin and the reciprocal
   direction in single precision, the slabs in single precision, mind MIN_ISECT_DEPTH and maxd
   the depth asked for *)
let met (b : float array) (o : Vec.t) (d : Vec.t) ~within =
  Array.length b = 0
  ||
  let slab k on dn =
    let inv = f32 (1. /. dn) and lo = b.(k) and hi = f32 (b.(k) +. b.(k + 3)) and on = f32 on in
    let near, far = if inv < 0. then (hi, lo) else (lo, hi) in
    (f32 (f32 (near -. on) *. inv), f32 (f32 (far -. on) *. inv))
  in
  let tmin, tmax = slab 0 o.x d.x and tymin, tymax = slab 1 o.y d.y in
  (not (tmin > tymax || tymin > tmax))
  &&
  let tmin = if tymin > tmin then tymin else tmin and tmax = if tymax < tmax then tymax else tmax in
  let tzmin, tzmax = slab 2 o.z d.z in
  (not (tmin > tzmax || tzmin > tmax))
  &&
  let tmin = if tzmin > tmin then tzmin else tmin and tmax = if tzmax < tmax then tzmax else tmax in
  tmin < f32 within && tmax > f32 Precision.min_isect_depth
