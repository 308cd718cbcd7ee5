(* The prism (shape/prism.cpp, parse.cpp: Parse_Prism): a closed 2-D spline curve in the XZ plane
   of prism space swept along Y, straight (linear_sweep) or towards the origin (conic_sweep),
   between two heights, capped unless open. Every rule, constant and operation order is
   POV-Ray's. *)

type spline = Linear | Quadratic | Cubic | Bezier

type segment = {
  x1 : float;
  y1 : float;
  x2 : float;
  y2 : float;
  v1 : float;
  u2 : float;
  v2 : float;
  ax : float;
  ay : float;
  bx : float;
  by : float;
  cx : float;
  cy : float;
  dx : float;
  dy : float;
}

type t = {
  spline : spline;
  conic : bool;
  height1 : float;
  height2 : float;
  closed : bool;
  sturm : bool;
  degenerate : bool;
  x1 : float;
  y1 : float;
  x2 : float;
  y2 : float;
  u1 : float;
  v1 : float;
  u2 : float;
  v2 : float;
  segs : segment array;
  tr : Transform.t;
  pbox : float array;
}

include Curve_hits.Limits
let base_hit = 1
let cap_hit = 2

(* ------------------------------------------------------------------------------------------ *)
(* Parsing: the outline's closing rule and the segments (Parse_Prism, Compute_Prism) *)

let near_point (px, py) (qx, qy) = Float.abs (px -. qx) < epsilon && Float.abs (py -. qy) < epsilon

(* the Bezier check's "same point": no coordinate more than EPSILON away *)
let same_point (px, py) (qx, qy) = not (Float.abs (px -. qx) > epsilon || Float.abs (py -. qy) > epsilon)

let close spline (pts : (float * float) array) =
  let n = Array.length pts in
  match spline with
  | Linear | Quadratic | Cubic ->
      let i = ref (if spline = Linear then 1 else 2) in
      let p = ref (if spline = Linear then pts.(0) else pts.(1)) in
      let closed = ref false in
      while !i < n do
        closed := false;
        if near_point !p pts.(!i) then begin
          let step = match spline with Linear -> 1 | Quadratic -> 2 | Cubic | Bezier -> 3 in
          i := !i + step;
          if !i < n then p := pts.(!i);
          closed := true
        end;
        incr i
      done;
      if !closed then (pts, `Closed)
      else if spline = Linear then (Array.append pts [| !p |], `Closing)
      else (pts, `Open)
  | Bezier when n = 0 ->
      (* no points (a count below 1): POV-Ray compares the last point, before its array, with
         its unset first, a read of whatever memory is there; POV-Ray 3.7.0.10 finds them equal
         (no warning), and the prism has no segments *)
      (pts, `Closed)
  | Bezier ->
      let closed = ref true and loop_start = ref 0 in
      let i = ref 4 in
      (try
         while !i < n do
           if not (same_point pts.(!i) pts.(!i - 1)) then begin
             if not (same_point pts.(!i - 1) pts.(!loop_start)) then begin
               closed := false;
               raise Exit
             end;
             loop_start := !i
           end;
           i := !i + 4
         done
       with Exit -> ());
      if not (same_point pts.(n - 1) pts.(!loop_start)) then closed := false;
      (pts, if !closed then `Closed else `Open)


(* The extremes of a quadratic or cubic segment's coordinate: the roots of its derivative within
   [0, 1] replace the end points' values at their index (x[n] = …, as POV-Ray writes them). *)
let extremes work a b c d (v : float array) =
  let cf = [| 3. *. a; 2. *. b; c |] and r = [| 0.; 0. |] in
  let n = Polysolv.solve work cf 2 ~sturm:false ~eps:0. r in
  for k = n - 1 downto 0 do
    if r.(k) >= 0. && r.(k) <= 1. then v.(k) <- (r.(k) *. ((r.(k) *. ((r.(k) *. a) +. b)) +. c)) +. d
  done

let compute ~spline ~conic ~height1 ~height2 (p : (float * float) array) =
  let number = Array.length p in
  let work = Polysolv.create () in
  let segs = ref [] in
  let xmin = ref bound_huge and xmax = ref (-.bound_huge) and ymin = ref bound_huge and ymax = ref (-.bound_huge) in
  let first = ref (match spline with Linear -> p.(0) | Quadratic | Cubic -> p.(1) | Bezier -> (0., 0.)) in
  let px i = fst p.(i) and py i = snd p.(i) in
  let i = ref 0 in
  let too_few = "Too few points in prism." and not_closed = "Too few points in prism. Prism not closed? Control points missing?" in
  while !i < number - 1 do
    let i0 = !i in
    let i1 = i0 + 1 and i2 = i0 + 2 and i3 = i0 + 3 in
    let x = Array.make 4 0. and y = Array.make 4 0. in
    let set4 v a b c d = v.(0) <- a; v.(1) <- b; v.(2) <- c; v.(3) <- d in
    let ax, bx, cx, dx, ay, by, cy, dy =
      match spline with
      | Linear ->
          if i1 >= number then failwith not_closed;
          set4 x (px i0) (px i1) (px i0) (px i1);
          set4 y (py i0) (py i1) (py i0) (py i1);
          (0., 0., (-1. *. px i0) +. (1. *. px i1), 1. *. px i0, 0., 0., (-1. *. py i0) +. (1. *. py i1), 1. *. py i0)
      | Quadratic ->
          if i2 >= number then failwith too_few;
          set4 x (px i1) (px i2) (px i1) (px i2);
          set4 y (py i1) (py i2) (py i1) (py i2);
          ( 0.,
            (0.5 *. px i0) -. (1. *. px i1) +. (0.5 *. px i2),
            (-0.5 *. px i0) +. (0.5 *. px i2),
            1. *. px i1,
            0.,
            (0.5 *. py i0) -. (1. *. py i1) +. (0.5 *. py i2),
            (-0.5 *. py i0) +. (0.5 *. py i2),
            1. *. py i1 )
      | Cubic ->
          if i3 >= number then failwith too_few;
          set4 x (px i1) (px i2) (px i1) (px i2);
          set4 y (py i1) (py i2) (py i1) (py i2);
          ( (-0.5 *. px i0) +. (1.5 *. px i1) -. (1.5 *. px i2) +. (0.5 *. px i3),
            px i0 -. (2.5 *. px i1) +. (2. *. px i2) -. (0.5 *. px i3),
            (-0.5 *. px i0) +. (0.5 *. px i2),
            px i1,
            (-0.5 *. py i0) +. (1.5 *. py i1) -. (1.5 *. py i2) +. (0.5 *. py i3),
            py i0 -. (2.5 *. py i1) +. (2. *. py i2) -. (0.5 *. py i3),
            (-0.5 *. py i0) +. (0.5 *. py i2),
            py i1 )
      | Bezier ->
          if i3 >= number then failwith not_closed;
          set4 x (px i0) (px i1) (px i2) (px i3);
          set4 y (py i0) (py i1) (py i2) (py i3);
          ( px i0 -. (3. *. px i1) +. (3. *. px i2) -. px i3,
            (3. *. px i1) -. (6. *. px i2) +. (3. *. px i3),
            (3. *. px i2) -. (3. *. px i3),
            px i3,
            py i0 -. (3. *. py i1) +. (3. *. py i2) -. py i3,
            (3. *. py i1) -. (6. *. py i2) +. (3. *. py i3),
            (3. *. py i2) -. (3. *. py i3),
            py i3 )
    in
    (match spline with
    | Quadratic | Cubic ->
        extremes work ax bx cx dx x;
        extremes work ay by cy dy y
    | Linear | Bezier -> ());
    let sx1 = cmin (cmin x.(0) x.(1)) (cmin x.(2) x.(3)) and sx2 = cmax (cmax x.(0) x.(1)) (cmax x.(2) x.(3)) in
    let sy1 = cmin (cmin y.(0) y.(1)) (cmin y.(2) y.(3)) and sy2 = cmax (cmax y.(0) y.(1)) (cmax y.(2) y.(3)) in
    segs := { x1 = sx1; y1 = sy1; x2 = sx2; y2 = sy2; v1 = sy1; u2 = sx2; v2 = sy2; ax; ay; bx; by; cx; cy; dx; dy } :: !segs;
    xmin := cmin !xmin sx1;
    xmax := cmax !xmax sx2;
    ymin := cmin !ymin sy1;
    ymax := cmax !ymax sy2;
    (* the next segment: past a closed sub-outline, the next one starts afresh *)
    (match spline with
    | Linear ->
        if near_point p.(i1) !first then begin
          incr i;
          if !i + 1 < number then first := p.(!i + 1)
        end
    | Quadratic ->
        if near_point p.(i2) !first then begin
          i := !i + 2;
          if !i + 2 < number then first := p.(!i + 2)
        end
    | Cubic ->
        if near_point p.(i2) !first then begin
          i := !i + 3;
          if !i + 2 < number then first := p.(!i + 2)
        end
    | Bezier -> i := !i + 3);
    incr i
  done;
  let segs = Array.of_list (List.rev !segs) in
  let x1 = !xmin and x2 = !xmax and y1 = !ymin and y2 = !ymax in
  if not conic then (segs, (x1, y1, x2, y2), (x1, y1, x2, y2))
  else begin
    (* the rectangles of a conic sweep reach from the base to the cap height *)
    let span a b =
      let v0 = a *. height1 and v1 = a *. height2 and v2 = b *. height1 and v3 = b *. height2 in
      (cmin (cmin v0 v1) (cmin v2 v3), cmax (cmax v0 v1) (cmax v2 v3))
    in
    let segs =
      Array.map
        (fun (s : segment) ->
          let x1, x2 = span s.x1 s.x2 and y1, y2 = span s.y1 s.y2 in
          { s with x1; x2; y1; y2 })
        segs
    in
    let bx1, bx2 = span x1 x2 and by1, by2 = span y1 y2 in
    (segs, (bx1, by1, bx2, by2), (x1, y1, x2, y2))
  end

(* ------------------------------------------------------------------------------------------ *)
(* Inside (in_curve: crossings of the ray from (u, v) towards +u) *)

let in_curve t work c roots u v =
  let nc = ref 0 in
  if u >= t.u1 && u <= t.u2 && v >= t.v1 && v <= t.v2 then
    Array.iter
      (fun (e : segment) ->
        if v >= e.v1 && v <= e.v2 && u <= e.u2 then begin
          c.(0) <- e.ay;
          c.(1) <- e.by;
          c.(2) <- e.cy;
          c.(3) <- e.dy -. v;
          let n = Polysolv.solve work c 3 ~sturm:t.sturm ~eps:0. roots in
          for k = n - 1 downto 0 do
            let w = roots.(k) in
            if w >= 0. && w <= 1. then begin
              let k = (w *. ((w *. ((w *. e.ax) +. e.bx)) +. e.cx)) +. e.dx -. u in
              if k >= 0. then incr nc
            end
          done
        end)
      t.segs;
  !nc land 1 = 1

(* test_rectangle: whether the 2-D ray P + t·D (x and z) meets the rectangle beyond EPSILON *)
let test_rectangle px pz dx dz x1 z1 x2 z2 =
  let exception Miss in
  try
    let dmin, dmax =
      if Float.abs dx > epsilon then begin
        let dmin, dmax =
          if dx > 0. then begin
            let dmin = (x1 -. px) /. dx and dmax = (x2 -. px) /. dx in
            if dmax < epsilon then raise Miss;
            (dmin, dmax)
          end
          else begin
            let dmax = (x1 -. px) /. dx in
            if dmax < epsilon then raise Miss;
            ((x2 -. px) /. dx, dmax)
          end
        in
        if dmin > dmax then raise Miss;
        (dmin, dmax)
      end
      else if px < x1 || px > x2 then raise Miss
      else (-.bound_huge, bound_huge)
    in
    if Float.abs dz > epsilon then begin
      let tmin, tmax = if dz > 0. then ((z1 -. pz) /. dz, (z2 -. pz) /. dz) else ((z2 -. pz) /. dz, (z1 -. pz) /. dz) in
      if tmax < dmax then begin
        if tmax < epsilon then raise Miss;
        if tmin > dmin then (if tmin > tmax then raise Miss) else if dmin > tmax then raise Miss
      end
      else if tmin > dmin && tmin > dmax then raise Miss
    end
    else if pz < z1 || pz > z2 then raise Miss;
    true
  with Miss -> false


(* All_Intersections: the crossings written into the scratch's curve room, in POV-Ray's order;
   their number *)
let crossings (w : Scratch.t) t (o : Vec.t) (d : Vec.t) =
  if t.degenerate then 0
  else begin
    let stats = w.stats in
    Stats.test stats Stats.prism;
    let m = t.tr in
    let p = Transform.inv_point m o and dv = Transform.inv_direction m d in
    let len = sqrt ((dv.x *. dv.x) +. (dv.y *. dv.y) +. (dv.z *. dv.z)) in
    let s = 1. /. len in
    let dx = dv.x *. s and dy = dv.y *. s and dz = dv.z *. s in
    let px = p.x and py = p.y and pz = p.z in
    let near = Curve_hits.near_limit w in
    Stats.test stats Stats.prism_bound;
    if (dx >= 0. && px > t.x2) || (dx <= 0. && px < t.x1) || (dz >= 0. && pz > t.y2) || (dz <= 0. && pz < t.y1) then 0
    else begin
      Stats.hit stats Stats.prism_bound;
      let k = ref 0 in
      let c = w.coeffs and roots = w.roots in
      let nseg = Array.length t.segs in
      let cap h part scaled =
        let kk = (h -. py) /. dy in
        if kk > near && kk < max_distance then begin
          let u = px +. (kk *. dx) and v = pz +. (kk *. dz) in
          let u, v = if scaled then (u /. h, v /. h) else (u, v) in
          if in_curve t w.quartic c roots u v then begin
            let distance = kk /. len in
            if distance > near && distance < max_distance then k := Curve_hits.add w !k distance part
          end
        end
      in
      let height_ok kk j wv =
        let h = py +. (kk *. dy) in
        if h >= t.height1 && h <= t.height2 then begin
          let distance = kk /. len in
          if distance > near && distance < max_distance then k := Curve_hits.add w !k distance (Curve_hits.spline_part ~segments:nseg j wv)
        end
      in
      let parallel = Float.abs dy < epsilon in
      if parallel && (py < t.height1 || py > t.height2) then 0
      else begin
        if (not parallel) && t.closed then begin
          if not t.conic then begin
            cap t.height2 cap_hit false;
            cap t.height1 base_hit false
          end
          else begin
            if Float.abs t.height2 > epsilon then cap t.height2 cap_hit true;
            if Float.abs t.height1 > epsilon then cap t.height1 base_hit true
          end
        end;
        if Float.abs dx > epsilon || Float.abs dz > epsilon then begin
          if not t.conic then
            Array.iteri
              (fun j (e : segment) ->
                Stats.test stats Stats.prism_bound;
                if not ((dx >= 0. && px > e.x2) || (dx <= 0. && px < e.x1) || (dz >= 0. && pz > e.y2) || (dz <= 0. && pz < e.y1)) then begin
                  let n =
                    match t.spline with
                    | Linear ->
                        Stats.hit stats Stats.prism_bound;
                        let x0 = (e.cx *. dz) -. (e.cy *. dx) in
                        let x1 = (dz *. (e.dx -. px)) -. (dx *. (e.dy -. pz)) in
                        if Float.abs x0 > epsilon then begin
                          roots.(0) <- -.x1 /. x0;
                          1
                        end
                        else 0
                    | Quadratic ->
                        Stats.hit stats Stats.prism_bound;
                        c.(0) <- (e.bx *. dz) -. (e.by *. dx);
                        c.(1) <- (e.cx *. dz) -. (e.cy *. dx);
                        c.(2) <- (dz *. (e.dx -. px)) -. (dx *. (e.dy -. pz));
                        Polysolv.solve w.quartic c 2 ~sturm:false ~eps:0. roots
                    | Cubic | Bezier ->
                        if test_rectangle px pz dx dz e.x1 e.y1 e.x2 e.y2 then begin
                          Stats.hit stats Stats.prism_bound;
                          c.(0) <- (e.ax *. dz) -. (e.ay *. dx);
                          c.(1) <- (e.bx *. dz) -. (e.by *. dx);
                          c.(2) <- (e.cx *. dz) -. (e.cy *. dx);
                          c.(3) <- (dz *. (e.dx -. px)) -. (dx *. (e.dy -. pz));
                          Polysolv.solve w.quartic c 3 ~sturm:t.sturm ~eps:0. roots
                        end
                        else 0
                  in
                  for r = n - 1 downto 0 do
                    let wv = roots.(r) in
                    if wv >= 0. && wv <= 1. then begin
                      let kk =
                        if Float.abs dx > epsilon then ((wv *. ((wv *. ((wv *. e.ax) +. e.bx)) +. e.cx)) +. e.dx -. px) /. dx
                        else ((wv *. ((wv *. ((wv *. e.ay) +. e.by)) +. e.cy)) +. e.dy -. pz) /. dz
                      in
                      height_ok kk j wv
                    end
                  done
                end)
              t.segs
          else begin
            let k1 = (pz *. dy) -. (py *. dz) and k2 = (py *. dx) -. (px *. dy) and k3 = (px *. dz) -. (pz *. dx) in
            Array.iteri
              (fun j (e : segment) ->
                if not ((dx >= 0. && px > e.x2) || (dx <= 0. && px < e.x1) || (dz >= 0. && pz > e.y2) || (dz <= 0. && pz < e.y1)) then begin
                  let n =
                    match t.spline with
                    | Linear ->
                        let x0 = (e.cx *. k1) +. (e.cy *. k2) in
                        let x1 = (e.dx *. k1) +. (e.dy *. k2) +. k3 in
                        if Float.abs x0 > epsilon then begin
                          roots.(0) <- -.x1 /. x0;
                          1
                        end
                        else 0
                    | Quadratic ->
                        c.(0) <- (e.bx *. k1) +. (e.by *. k2);
                        c.(1) <- (e.cx *. k1) +. (e.cy *. k2);
                        c.(2) <- (e.dx *. k1) +. (e.dy *. k2) +. k3;
                        Polysolv.solve w.quartic c 2 ~sturm:false ~eps:0. roots
                    | Cubic | Bezier ->
                        c.(0) <- (e.ax *. k1) +. (e.ay *. k2);
                        c.(1) <- (e.bx *. k1) +. (e.by *. k2);
                        c.(2) <- (e.cx *. k1) +. (e.cy *. k2);
                        c.(3) <- (e.dx *. k1) +. (e.dy *. k2) +. k3;
                        Polysolv.solve w.quartic c 3 ~sturm:t.sturm ~eps:0. roots
                  in
                  for r = n - 1 downto 0 do
                    let wv = roots.(r) in
                    if wv >= 0. && wv <= 1. then begin
                      let kx = (wv *. ((wv *. ((wv *. e.ax) +. e.bx)) +. e.cx)) +. e.dx in
                      let h = dx -. (kx *. dy) in
                      if Float.abs h > epsilon then height_ok (((kx *. py) -. px) /. h) j wv
                      else begin
                        let kz = (wv *. ((wv *. ((wv *. e.ay) +. e.by)) +. e.cy)) +. e.dy in
                        let h = dz -. (kz *. dy) in
                        if Float.abs h > epsilon then height_ok (((kz *. py) -. pz) /. h) j wv
                      end
                    end
                  done
                end)
              t.segs
          end
        end;
        if !k > 0 then Stats.hit stats Stats.prism;
        !k
      end
    end
  end

(* a top-level prism is tried only when the ray passes its box (Trace::FindIntersection) *)
let depth (w : Scratch.t) t o d lo = if w.robust || Curve_hits.box_admits t.pbox o d then Curve_hits.nearest w (crossings w t o d) lo else infinity
let hits w t id o d lo n = Curve_hits.push w (crossings w t o d) id o d lo n

let inside t (p : Vec.t) =
  let q = Transform.inv_point t.tr p in
  q.y >= t.height1 && q.y < t.height2
  &&
  let u, v =
    if not t.conic then (q.x, q.z) else if Float.abs q.y > epsilon then (q.x /. q.y, q.z /. q.y) else (Float.infinity, Float.infinity)
  in
  in_curve t (Polysolv.create ()) (Array.make 4 0.) (Array.make 3 0.) u v

let normal t part (p : Vec.t) =
  let nseg = Array.length t.segs in
  let n =
    if part < 3 then Vec.make 0. 1. 0.
    else begin
      let e = t.segs.(Curve_hits.segment ~segments:nseg part) and d1 = Curve_hits.parameter ~segments:nseg part in
      let nx = (d1 *. ((3. *. e.ay *. d1) +. (2. *. e.by))) +. e.cy in
      let nz = -.((d1 *. ((3. *. e.ax *. d1) +. (2. *. e.bx))) +. e.cx) in
      if not t.conic then Vec.make nx 0. nz
      else begin
        let q = Transform.inv_point t.tr p in
        if Float.abs q.y > epsilon then Vec.make nx (-.((q.x *. nx) +. (q.z *. nz)) /. q.y) nz else Vec.make 0. 1. 0.
      end
    end
  in
  Transform.normalize (Transform.normal t.tr n)

let box t = [| t.x1; t.height1; t.y1; t.x2; t.height2; t.y2 |]
let bounds t = Transform.bounds t.tr (box t)
let pov_box t = let b = box t in Pov_box.mapped t.tr (Pov_box.of_min_max (Array.sub b 0 3) (Array.sub b 3 3))
let transform t m =
  let t = { t with tr = Transform.compose t.tr m } in
  { t with pbox = pov_box t }

let make ~spline ~conic ~height1 ~height2 ~closed ~sturm ~degenerate pts =
  match compute ~spline ~conic ~height1 ~height2 pts with
  | exception Failure msg -> Error msg
  | segs, (x1, y1, x2, y2), (u1, v1, u2, v2) ->
      let t = { spline; conic; height1; height2; closed; sturm; degenerate; x1; y1; x2; y2; u1; v1; u2; v2; segs; tr = Transform.identity; pbox = [||] } in
      Ok { t with pbox = pov_box t }

let traits = { Traits.default with name = "prism"; sturm = Sturm_flag }
