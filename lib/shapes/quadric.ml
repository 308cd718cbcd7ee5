(* The quadric, after POV-Ray 3.7's shape/quadrics.cpp: every formula keeps its operation order,
   since the last bit of a root or of a transformed coefficient can decide a pixel. *)

type t = {
  xx : float;
  yy : float;
  zz : float;
  xy : float;
  xz : float;
  yz : float;
  lx : float;
  ly : float;
  lz : float;
  k : float;
  box_llx : float;
  box_lly : float;
  box_llz : float;
  box_lenx : float;
  box_leny : float;
  box_lenz : float;
}

let f32 = Precision.f32
let epsilon = Precision.epsilon

(* BOUND_HUGE, and CRITICAL_LENGTH: a box longer than this on any axis is made the huge box *)
let bound_huge = 2e10
let critical_length = 1e6

let box q = [| q.box_llx; q.box_lly; q.box_llz; q.box_lenx; q.box_leny; q.box_lenz |]

let with_box q (b : float array) =
  { q with box_llx = b.(0); box_lly = b.(1); box_llz = b.(2); box_lenx = b.(3); box_leny = b.(4); box_lenz = b.(5) }

(* Make_BBox: the values as given, in single precision *)
let huge_box =
  let lo = f32 (-.bound_huge /. 2.) and len = f32 bound_huge in
  [| lo; lo; lo; len; len; len |]

(* Make_BBox_from_min_max: the lower corner and the lengths (computed in double) in single precision *)
let of_min_max (lo : float array) (hi : float array) =
  [| f32 lo.(0); f32 lo.(1); f32 lo.(2); f32 (hi.(0) -. lo.(0)); f32 (hi.(1) -. lo.(1)); f32 (hi.(2) -. lo.(2)) |]


(* std::max and std::min, which keep the first argument unless the second is larger (smaller) *)
let maxf (a : float) b = if a < b then b else a
let minf (a : float) b = if b < a then b else a

(* Quadric::Compute_BBox(ClipMin, ClipMax), with [old] the box the quadric has. The letters are
   POV-Ray's own here, not the scene language's: A, E, H the square terms, B, C, F half the mixed
   ones (xy, xz, yz), D, G, I half the linear ones, J the constant. *)
let compute_box q ~old (clip_min : float array) (clip_max : float array) =
  let zero v = if Float.abs v < epsilon then 0. else v in
  let a = zero q.xx and e = zero q.yy and h = zero q.zz in
  let b = zero (q.xy /. 2.) and c = zero (q.xz /. 2.) and f = zero (q.yz /. 2.) in
  let d = zero (q.lx /. 2.) and g = zero (q.ly /. 2.) and i = zero (q.lz /. 2.) and j = zero q.k in
  let cmin = Array.copy clip_min and cmax = Array.copy clip_max in
  if b <> 0. || c <> 0. || f <> 0. then begin
    (* not in a normal form: at best the clipping box *)
    let v = (cmax.(0) -. cmin.(0)) *. (cmax.(1) -. cmin.(1)) *. (cmax.(2) -. cmin.(2)) in
    if v < Pov_box.volume old then of_min_max cmin cmax else old
  end
  else begin
    (* linear terms: the translation that removes them where a square term allows it *)
    let tx, ty, tz, d, g, i, j =
      if d <> 0. || g <> 0. || i <> 0. then begin
        let shift a d = if a <> 0. then -.d /. a else if d <> 0. then j /. (2.0 *. d) else 0. in
        let tx = shift a d and ty = shift e g and tz = shift h i in
        let d = d +. (a *. tx) and g = g +. (e *. ty) and i = i +. (h *. tz) in
        let j = j -. ((tx *. ((a *. tx) +. (2.0 *. d))) +. (ty *. ((e *. ty) +. (2.0 *. g))) +. (tz *. ((h *. tz) +. (2.0 *. i)))) in
        (tx, ty, tz, d, g, i, j)
      end
      else (0., 0., 0., d, g, i, j)
    in
    let nmin = Array.make 3 (-.bound_huge /. 2.) and nmax = Array.make 3 (bound_huge /. 2.) in
    cmin.(0) <- cmin.(0) -. tx; cmin.(1) <- cmin.(1) -. ty; cmin.(2) <- cmin.(2) -. tz;
    cmax.(0) <- cmax.(0) -. tx; cmax.(1) <- cmax.(1) -. ty; cmax.(2) <- cmax.(2) -. tz;
    (* A made non-negative *)
    let a, d, e, g, h, i, j = if a < 0. then (-.a, -.d, -.e, -.g, -.h, -.i, -.j) else (a, d, e, g, h, i, j) in
    let set_y_z ry rz = nmin.(1) <- -.ry; nmin.(2) <- -.rz; nmax.(1) <- ry; nmax.(2) <- rz in
    let set_x_z rx rz = nmin.(0) <- -.rx; nmin.(2) <- -.rz; nmax.(0) <- rx; nmax.(2) <- rz in
    let set_x_y rx ry = nmin.(0) <- -.rx; nmin.(1) <- -.ry; nmax.(0) <- rx; nmax.(1) <- ry in
    (* each form is tested in turn, and a later one that also holds overrides *)
    if a > 0. && e > 0. && h > 0. && j < 0. then begin
      (* ellipsoid *)
      let ra = sqrt (-.j /. a) and rb = sqrt (-.j /. e) and rc = sqrt (-.j /. h) in
      nmin.(0) <- -.ra; nmin.(1) <- -.rb; nmin.(2) <- -.rc;
      nmax.(0) <- ra; nmax.(1) <- rb; nmax.(2) <- rc
    end;
    (* cylinders along x, y, z *)
    if a = 0. && e > 0. && h > 0. && j < 0. then set_y_z (sqrt (-.j /. e)) (sqrt (-.j /. h));
    if a > 0. && e = 0. && h > 0. && j < 0. then set_x_z (sqrt (-.j /. a)) (sqrt (-.j /. h));
    if a > 0. && e > 0. && h = 0. && j < 0. then set_x_y (sqrt (-.j /. a)) (sqrt (-.j /. e));
    (* cones along x, y, z: the radii at the clipping box's ends *)
    if a > 0. && e < 0. && h < 0. && j = 0. then begin
      let ra = sqrt (1.0 /. a) and rb = sqrt (-1.0 /. e) and rc = sqrt (-1.0 /. h) in
      let ry x = Float.abs (x *. rb /. ra) and rz x = Float.abs (x *. rc /. ra) in
      set_y_z (maxf (ry cmin.(0)) (ry cmax.(0))) (maxf (rz cmin.(0)) (rz cmax.(0)))
    end;
    if a > 0. && e < 0. && h > 0. && j = 0. then begin
      let ra = sqrt (1.0 /. a) and rb = sqrt (-1.0 /. e) and rc = sqrt (1.0 /. h) in
      let rx y = Float.abs (y *. ra /. rb) and rz y = Float.abs (y *. rc /. rb) in
      set_x_z (maxf (rx cmin.(1)) (rx cmax.(1))) (maxf (rz cmin.(1)) (rz cmax.(1)))
    end;
    if a > 0. && e > 0. && h < 0. && j = 0. then begin
      let ra = sqrt (1.0 /. a) and rb = sqrt (1.0 /. e) and rc = sqrt (-1.0 /. h) in
      let rx z = Float.abs (z *. ra /. rc) and ry z = Float.abs (z *. rb /. rc) in
      set_x_y (maxf (rx cmin.(2)) (rx cmax.(2))) (maxf (ry cmin.(2)) (ry cmax.(2)))
    end;
    (* hyperboloids along x, y, z (the formulas assume |J| = 1) *)
    if a > 0. && e < 0. && h < 0. && j > 0. then begin
      let ry x = sqrt (-.(1.0 +. (a *. (x *. x))) /. e) and rz x = sqrt (-.(1.0 +. (a *. (x *. x))) /. h) in
      set_y_z (maxf (ry cmin.(0)) (ry cmax.(0))) (maxf (rz cmin.(0)) (rz cmax.(0)))
    end;
    if a > 0. && e < 0. && h > 0. && j < 0. then begin
      let rx y = sqrt ((1.0 -. (e *. (y *. y))) /. a) and rz y = sqrt ((1.0 -. (e *. (y *. y))) /. h) in
      set_x_z (maxf (rx cmin.(1)) (rx cmax.(1))) (maxf (rz cmin.(1)) (rz cmax.(1)))
    end;
    if a > 0. && e > 0. && h < 0. && j < 0. then begin
      let rx z = sqrt ((1.0 -. (h *. (z *. z))) /. a) and ry z = sqrt ((1.0 -. (h *. (z *. z))) /. e) in
      set_x_y (maxf (rx cmin.(2)) (rx cmax.(2))) (maxf (ry cmin.(2)) (ry cmax.(2)))
    end;
    (* paraboloids along x, y, z: open towards one side of the vertex *)
    if a = 0. && d <> 0. && e *. h > 0. && j = 0. then begin
      let lo = if d *. e < 0. then maxf 0. cmin.(0) else cmin.(0) in
      let hi = if d *. e > 0. then minf 0. cmax.(0) else cmax.(0) in
      let ry x = sqrt (Float.abs (2.0 *. d *. x /. e)) and rz x = sqrt (Float.abs (2.0 *. d *. x /. h)) in
      set_y_z (maxf (ry lo) (ry hi)) (maxf (rz lo) (rz hi));
      if d *. e < 0. then nmin.(0) <- maxf 0. cmin.(0);
      if d *. e > 0. then nmax.(0) <- minf 0. cmax.(0)
    end;
    if e = 0. && g <> 0. && a *. h > 0. && j = 0. then begin
      let lo = if g > 0. then cmin.(1) else maxf 0. cmin.(1) in
      let hi = if g < 0. then cmax.(1) else minf 0. cmax.(1) in
      let rx y = sqrt (Float.abs (2.0 *. g *. y /. a)) and rz y = sqrt (Float.abs (2.0 *. g *. y /. h)) in
      set_x_z (maxf (rx lo) (rx hi)) (maxf (rz lo) (rz hi));
      if g < 0. then nmin.(1) <- maxf 0. cmin.(1);
      if g > 0. then nmax.(1) <- minf 0. cmax.(1)
    end;
    if h = 0. && i <> 0. && a *. e > 0. && j = 0. then begin
      let lo = if i < 0. then maxf cmin.(2) 0. else cmin.(2) in
      let hi = if i > 0. then minf 0. cmax.(2) else cmax.(2) in
      let rx z = sqrt (Float.abs (2.0 *. i *. z /. a)) and ry z = sqrt (Float.abs (2.0 *. i *. z /. e)) in
      set_x_y (maxf (rx lo) (rx hi)) (maxf (ry lo) (ry hi));
      if i < 0. then nmin.(2) <- maxf cmin.(2) 0.;
      if i > 0. then nmax.(2) <- minf cmax.(2) 0.
    end;
    for k = 0 to 2 do
      nmin.(k) <- maxf nmin.(k) cmin.(k);
      nmax.(k) <- minf nmax.(k) cmax.(k)
    done;
    let v = (nmax.(0) -. nmin.(0)) *. (nmax.(1) -. nmin.(1)) *. (nmax.(2) -. nmin.(2)) in
    if v < Pov_box.volume old then begin
      let t = [| tx; ty; tz |] in
      let b = of_min_max (Array.init 3 (fun k -> nmin.(k) +. t.(k))) (Array.init 3 (fun k -> nmax.(k) +. t.(k))) in
      if b.(3) > critical_length || b.(4) > critical_length || b.(5) > critical_length then huge_box else b
    end
    else old
  end

let box_within q lo hi = compute_box q ~old:(box q) lo hi

let make ~(square : Vec.t) ~(mixed : Vec.t) ~(linear : Vec.t) j =
  let q =
    {
      xx = square.x; yy = square.y; zz = square.z;
      xy = mixed.x; xz = mixed.y; yz = mixed.z;
      lx = linear.x; ly = linear.y; lz = linear.z;
      k = j;
      box_llx = 0.; box_lly = 0.; box_llz = 0.; box_lenx = 0.; box_leny = 0.; box_lenz = 0.;
    }
  in
  (* a new object has the huge box; Parse_Quadric then bounds it within ±BOUND_HUGE *)
  let whole = Array.make 3 bound_huge in
  with_box q (compute_box q ~old:huge_box (Array.map Float.neg whole) whole)

let transform q tr =
  (* Quadric_To_Matrix: the coefficients in the upper triangle *)
  let m = Array.make 16 0. in
  m.(0) <- q.xx; m.(5) <- q.yy; m.(10) <- q.zz;
  m.(1) <- q.xy; m.(2) <- q.xz; m.(6) <- q.yz;
  m.(3) <- q.lx; m.(7) <- q.ly; m.(11) <- q.lz;
  m.(15) <- q.k;
  let inv = Transform.inverse_matrix tr in
  let inv_t = Array.init 16 (fun n -> inv.((4 * (n mod 4)) + (n / 4))) in
  (* MTimesB(I, Q), then MTimesA(Q, Iᵀ) *)
  let m = Transform.product (Transform.product inv m) inv_t in
  let b = box q in
  (* Recompute_BBox: the box's corners mapped by this one transform *)
  let moved = Transform.bounds tr [| b.(0); b.(1); b.(2); b.(0) +. b.(3); b.(1) +. b.(4); b.(2) +. b.(5) |] in
  with_box
    {
      q with
      xx = m.(0); yy = m.(5); zz = m.(10);
      xy = m.(1) +. m.(4); xz = m.(2) +. m.(8); yz = m.(6) +. m.(9);
      lx = m.(3) +. m.(12); ly = m.(7) +. m.(13); lz = m.(11) +. m.(14);
      k = m.(15);
    }
    (of_min_max (Array.sub moved 0 3) (Array.sub moved 3 3))

let invert q =
  {
    q with
    xx = -.q.xx; yy = -.q.yy; zz = -.q.zz;
    xy = -.q.xy; xz = -.q.xz; yz = -.q.yz;
    lx = -.q.lx; ly = -.q.ly; lz = -.q.lz;
    k = -.q.k;
  }

(* Quadric::Intersect, in world space (the direction is unit length), then All_Intersections'
   depth limits *)
let intersect (stats : Stats.t) (lim : Limits.t) q (o : Vec.t) (d : Vec.t) (out : float array) =
  Stats.test stats Stats.quadric;
  let xd = d.x and yd = d.y and zd = d.z and xo = o.x and yo = o.y and zo = o.z in
  let a = (xd *. ((q.xx *. xd) +. (q.xy *. yd) +. (q.xz *. zd))) +. (yd *. ((q.yy *. yd) +. (q.yz *. zd))) +. (zd *. q.zz *. zd) in
  let b =
    (xd *. ((q.xx *. xo) +. (0.5 *. ((q.xy *. yo) +. (q.xz *. zo) +. q.lx))))
    +. (yd *. ((q.yy *. yo) +. (0.5 *. ((q.xy *. xo) +. (q.yz *. zo) +. q.ly))))
    +. (zd *. ((q.zz *. zo) +. (0.5 *. ((q.xz *. xo) +. (q.yz *. yo) +. q.lz))))
  in
  let c =
    (xo *. ((q.xx *. xo) +. (q.xy *. yo) +. (q.xz *. zo) +. q.lx))
    +. (yo *. ((q.yy *. yo) +. (q.yz *. zo) +. q.ly))
    +. (zo *. ((q.zz *. zo) +. q.lz))
    +. q.k
  in
  if a <> 0.0 then begin
    let disc = (b *. b) -. (a *. c) in
    if disc <= 0.0 then 0
    else begin
      Stats.hit stats Stats.quadric;
      let s = sqrt disc in
      let t1 = (-.b +. s) /. a and t2 = (-.b -. s) /. a in
      let n = if t1 > lim.near && t1 < lim.far then (out.(0) <- t1; 1) else 0 in
      if t2 > lim.near && t2 < lim.far then (out.(n) <- t2; n + 1) else n
    end
  end
  else if b = 0.0 then 0
  else begin
    (* no square term along the ray: one root; POV-Ray's second "root" is MAX_DISTANCE itself,
       which its test never keeps *)
    Stats.hit stats Stats.quadric;
    let t1 = -0.5 *. c /. b in
    if t1 > lim.near && t1 < lim.far then (out.(0) <- t1; 1) else 0
  end

let normal q (p : Vec.t) =
  let nx = (2.0 *. q.xx *. p.x) +. (q.xy *. p.y) +. (q.xz *. p.z) +. q.lx in
  let ny = (q.xy *. p.x) +. (2.0 *. q.yy *. p.y) +. (q.yz *. p.z) +. q.ly in
  let nz = (q.xz *. p.x) +. (q.yz *. p.y) +. (2.0 *. q.zz *. p.z) +. q.lz in
  let len = sqrt ((nx *. nx) +. (ny *. ny) +. (nz *. nz)) in
  if len = 0.0 then Vec.make 1. 0. 0.
  else
    let s = 1. /. len in
    Vec.make (nx *. s) (ny *. s) (nz *. s)

let inside q (p : Vec.t) =
  (p.x *. ((q.xx *. p.x) +. (q.xy *. p.y) +. q.lx))
  +. (p.y *. ((q.yy *. p.y) +. (q.yz *. p.z) +. q.ly))
  +. (p.z *. ((q.zz *. p.z) +. (q.xz *. p.x) +. q.lz))
  +. q.k
  <= 0.0

let pov_box q = if Pov_box.infinite (box q) then [||] else box q

(* a POV-Ray box as min and max (in double, as Make_min_max_from_BBox): the single-precision box
   culls rays before the quadric is tried (Intersect_BBox), so it is the box, not a wider one *)
let min_max b =
  if Pov_box.infinite b then None
  else
    let hi k = b.(k) +. b.(k + 3) in
    Some [| b.(0); b.(1); b.(2); hi 0; hi 1; hi 2 |]

let bounds q = min_max (box q)
let bounds_within q lo hi = min_max (box_within q lo hi)

let magnitude q =
  match bounds q with
  | Some b -> Array.fold_left (fun m v -> Float.max m (Float.abs v)) 0. b
  | None ->
      let square = List.fold_left Float.max 0. (List.map Float.abs [ q.xx; q.yy; q.zz; q.xy; q.xz; q.yz ]) in
      let linear = List.fold_left Float.max 0. (List.map Float.abs [ q.lx; q.ly; q.lz ]) in
      if square > 0. then Float.max (sqrt (Float.abs q.k /. square)) (linear /. square)
      else if linear > 0. then Float.abs q.k /. linear
      else 0.

let depth (w : Scratch.t) q o d lo = Scratch.nearest_depth w (intersect w.stats w.lim q o d w.crossings) lo

(* Quadric::All_Intersections: the roots in the order found *)
let hits (w : Scratch.t) q id o d lo n =
  let k = intersect w.stats w.lim q o d w.crossings in
  let n = if k > 0 then Scratch.push_ray w n lo w.crossings.(0) (-1) id o d else n in
  if k > 1 then Scratch.push_ray w n lo w.crossings.(1) (-1) id o d else n

let traits = { Traits.default with name = "quadric"; inside_holds_inverse = true }
