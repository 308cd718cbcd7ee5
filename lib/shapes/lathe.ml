(* The lathe (shape/lathe.cpp, parse.cpp: Parse_Lathe): a 2-D spline (radius, height) rotated about
   the Y axis, each segment met by the polynomial of degree 2, 4 or 6 that its spline type gives.
   Every rule, constant and operation order is POV-Ray's. *)

type spline = Prism.spline

type segment = { ax : float; ay : float; bx : float; by : float; cx : float; cy : float; dx : float; dy : float }

type t = {
  spline : spline;
  segs : segment array;
  bcyl : Bcyl.t;
  height1 : float;
  height2 : float;
  radius1 : float;
  radius2 : float;
  sturm : bool;
  tr : Transform.t;
  pbox : float array;
}

include Curve_hits.Limits

let segment_count (spline : spline) n = match spline with Linear -> n - 1 | Quadratic -> n - 2 | Cubic -> n - 3 | Bezier -> n / 4

let pov_box t = Curve_hits.revolution_pov_box t.tr ~radius2:t.radius2 ~height1:t.height1 ~height2:t.height2

(* Compute_Lathe *)
let make ~spline ~sturm (p : (float * float) array) =
  let number = segment_count spline (Array.length p) in
  let px i = fst p.(i) and py i = snd p.(i) in
  let work = Polysolv.create () in
  let r1 = Array.make number 0. and r2 = Array.make number 0. and h1 = Array.make number 0. and h2 = Array.make number 0. in
  let xmin = ref bound_huge and xmax = ref (-.bound_huge) and ymin = ref bound_huge and ymax = ref (-.bound_huge) in
  let extremes a b c d (v : float array) =
    let cf = [| 3. *. a; 2. *. b; c |] and r = [| 0.; 0. |] in
    let n = Polysolv.solve work cf 2 ~sturm:false ~eps:0. r in
    for k = n - 1 downto 0 do
      if r.(k) >= 0. && r.(k) <= 1. then v.(k) <- (r.(k) *. ((r.(k) *. ((r.(k) *. a) +. b)) +. c)) +. d
    done
  in
  let segs =
    Array.init number (fun segment ->
        let i = match spline with Bezier -> 4 * segment | Linear | Quadratic | Cubic -> segment in
        let i1 = i + 1 and i2 = i + 2 and i3 = i + 3 in
        let x, y, s =
          match spline with
          | Linear ->
              ( [| px i; px i1; px i; px i1 |],
                [| py i; py i1; py i; py i1 |],
                { ax = 0.; bx = 0.; cx = (-1. *. px i) +. (1. *. px i1); dx = 1. *. px i;
                  ay = 0.; by = 0.; cy = (-1. *. py i) +. (1. *. py i1); dy = 1. *. py i } )
          | Quadratic ->
              ( [| px i1; px i2; px i1; px i2 |],
                [| py i1; py i2; py i1; py i2 |],
                { ax = 0.; bx = (0.5 *. px i) -. (1. *. px i1) +. (0.5 *. px i2); cx = (-0.5 *. px i) +. (0.5 *. px i2); dx = 1. *. px i1;
                  ay = 0.; by = (0.5 *. py i) -. (1. *. py i1) +. (0.5 *. py i2); cy = (-0.5 *. py i) +. (0.5 *. py i2); dy = 1. *. py i1 } )
          | Cubic ->
              ( [| px i1; px i2; px i1; px i2 |],
                [| py i1; py i2; py i1; py i2 |],
                {
                  ax = (-0.5 *. px i) +. (1.5 *. px i1) -. (1.5 *. px i2) +. (0.5 *. px i3);
                  bx = px i -. (2.5 *. px i1) +. (2. *. px i2) -. (0.5 *. px i3);
                  cx = (-0.5 *. px i) +. (0.5 *. px i2);
                  dx = px i1;
                  ay = (-0.5 *. py i) +. (1.5 *. py i1) -. (1.5 *. py i2) +. (0.5 *. py i3);
                  by = py i -. (2.5 *. py i1) +. (2. *. py i2) -. (0.5 *. py i3);
                  cy = (-0.5 *. py i) +. (0.5 *. py i2);
                  dy = py i1;
                } )
          | Bezier ->
              ( [| px i; px i1; px i2; px i3 |],
                [| py i; py i1; py i2; py i3 |],
                {
                  ax = px i3 -. (3. *. px i2) +. (3. *. px i1) -. px i;
                  bx = (3. *. px i2) -. (6. *. px i1) +. (3. *. px i);
                  cx = (3. *. px i1) -. (3. *. px i);
                  dx = px i;
                  ay = py i3 -. (3. *. py i2) +. (3. *. py i1) -. py i;
                  by = (3. *. py i2) -. (6. *. py i1) +. (3. *. py i);
                  cy = (3. *. py i1) -. (3. *. py i);
                  dy = py i;
                } )
        in
        (match spline with
        | Quadratic | Cubic ->
            extremes s.ax s.bx s.cx s.dx x;
            extremes s.ay s.by s.cy s.dy y
        | Linear | Bezier -> ());
        r1.(segment) <- cmin (cmin x.(0) x.(1)) (cmin x.(2) x.(3));
        r2.(segment) <- cmax (cmax x.(0) x.(1)) (cmax x.(2) x.(3));
        h1.(segment) <- cmin (cmin y.(0) y.(1)) (cmin y.(2) y.(3));
        h2.(segment) <- cmax (cmax y.(0) y.(1)) (cmax y.(2) y.(3));
        xmin := cmin !xmin r1.(segment);
        xmax := cmax !xmax r2.(segment);
        ymin := cmin !ymin h1.(segment);
        ymax := cmax !ymax h2.(segment);
        s)
  in
  { spline; segs; bcyl = Bcyl.make r1 r2 h1 h2; height1 = !ymin; height2 = !ymax; radius1 = !xmin; radius2 = !xmax; sturm; tr = Transform.identity; pbox = [||] }
  |> fun t -> { t with pbox = pov_box t }

let transform t m =
  let t = { t with tr = Transform.compose t.tr m } in
  { t with pbox = pov_box t }

let crossings (w : Scratch.t) t ~all (o : Vec.t) (dir : Vec.t) =
  let stats = w.stats in
  Stats.test stats Stats.lathe;
  let p = Transform.inv_point t.tr o and dv = Transform.inv_direction t.tr dir in
  let len = sqrt ((dv.x *. dv.x) +. (dv.y *. dv.y) +. (dv.z *. dv.z)) in
  let s = 1. /. len in
  let dx = dv.x *. s and dy = dv.y *. s and dz = dv.z *. s in
  let px = p.x and py = p.y and pz = p.z in
  let dylen = dy *. len in
  let near = Curve_hits.near_limit w in
  Stats.test stats Stats.lathe_bound;
  if (dy >= 0. && py > t.height2) || (dy <= 0. && py < t.height1) || (dx >= 0. && px > t.radius2) || (dx <= 0. && px < -.t.radius2) then 0
  else begin
    let r0 = Float.abs ((px *. dz) -. (pz *. dx)) in
    let r = (dx *. dx) +. (dz *. dz) in
    let r0 = if r > 0. then r0 /. sqrt r else r0 in
    if r0 > t.radius2 then 0
    else begin
      let cnt = Bcyl.intersect w t.bcyl px py pz dx dy dz in
      if cnt = 0 then 0
      else begin
        Stats.hit stats Stats.lathe_bound;
        let m = (dx *. px) +. (dz *. pz) and dy2 = dy *. dy in
        let k = ref 0 and best = ref bound_huge in
        let nseg = Array.length t.segs in
        let c = w.coeffs and roots = w.roots in
        let c6 = w.sextic_coeffs and roots6 = w.sextic_roots in
        let hit d wv seg = if d > near && d < max_distance then (k := Curve_hits.add w !k d (Curve_hits.spline_part ~segments:nseg seg wv); true) else false in
        (try
           for j = 0 to cnt - 1 do
             let seg = Bcyl.interval_segment w j in
             let e = t.segs.(seg) in
             if (not all) && Bcyl.interval_depth w j > !best then raise Exit;
             let dyp = e.dy -. py in
             let n, rs =
               match t.spline with
               | Linear ->
                   c.(0) <- (e.cy *. e.cy *. r) -. (e.cx *. e.cx *. dy2);
                   c.(1) <- 2. *. ((e.cy *. ((dyp *. r) +. (dy *. m))) -. (e.cx *. e.dx *. dy2));
                   c.(2) <- (dyp *. ((dyp *. r) +. (2. *. dy *. m))) +. (dy2 *. ((px *. px) +. (pz *. pz) -. (e.dx *. e.dx)));
                   (Polysolv.solve w.quartic c 2 ~sturm:false ~eps:0. roots, roots)
               | Quadratic ->
                   c.(0) <- (e.by *. e.by *. r) -. (e.bx *. e.bx *. dy2);
                   c.(1) <- 2. *. ((e.by *. e.cy *. r) -. (e.bx *. e.cx *. dy2));
                   c.(2) <-
                     (r *. ((2. *. e.by *. dyp) +. (e.cy *. e.cy))) +. (2. *. e.by *. dy *. m) -. (((2. *. e.bx *. e.dx) +. (e.cx *. e.cx)) *. dy2);
                   c.(3) <- 2. *. ((e.cy *. ((dyp *. r) +. (dy *. m))) -. (e.cx *. e.dx *. dy2));
                   c.(4) <- (dyp *. ((dyp *. r) +. (2. *. dy *. m))) +. (dy2 *. ((px *. px) +. (pz *. pz) -. (e.dx *. e.dx)));
                   (Polysolv.solve w.quartic c 4 ~sturm:t.sturm ~eps:0. roots, roots)
               | Cubic | Bezier ->
                   c6.(0) <- (e.ay *. e.ay *. r) -. (e.ax *. e.ax *. dy2);
                   c6.(1) <- 2. *. ((e.ay *. e.by *. r) -. (e.ax *. e.bx *. dy2));
                   c6.(2) <- (((2. *. e.ay *. e.cy) +. (e.by *. e.by)) *. r) -. (((2. *. e.ax *. e.cx) +. (e.bx *. e.bx)) *. dy2);
                   c6.(3) <-
                     2.
                     *. (((((e.ay *. e.dy) +. (e.by *. e.cy)) -. (e.ay *. py)) *. r) +. (e.ay *. dy *. m)
                        -. (((e.ax *. e.dx) +. (e.bx *. e.cx)) *. dy2));
                   c6.(4) <-
                     (((2. *. e.by *. dyp) +. (e.cy *. e.cy)) *. r) +. (2. *. e.by *. dy *. m) -. (((2. *. e.bx *. e.dx) +. (e.cx *. e.cx)) *. dy2);
                   c6.(5) <- 2. *. ((e.cy *. ((dyp *. r) +. (dy *. m))) -. (e.cx *. e.dx *. dy2));
                   c6.(6) <- (dyp *. ((dyp *. r) +. (2. *. dy *. m))) +. (dy2 *. ((px *. px) +. (pz *. pz) -. (e.dx *. e.dx)));
                   (Polysolv.solve w.sextic c6 6 ~sturm:t.sturm ~eps:0. roots6, roots6)
             in
             for q = n - 1 downto 0 do
               let wv = rs.(q) in
               if wv >= 0. && wv <= 1. then begin
                 if Float.abs dy > epsilon then begin
                   let kk = (wv *. ((wv *. ((wv *. e.ay) +. e.by)) +. e.cy)) +. e.dy -. py in
                   if hit (kk /. dylen) wv seg then begin
                     let kk = kk /. dy in
                     if kk < !best then best := kk
                   end
                 end
                 else begin
                   let kr = (wv *. ((wv *. ((wv *. e.ax) +. e.bx)) +. e.cx)) +. e.dx in
                   let x2 = w.lathe_quadratic in
                   x2.(0) <- r;
                   x2.(1) <- 2. *. m;
                   x2.(2) <- (px *. px) +. (pz *. pz) -. (kr *. kr);
                   let y2 = w.lathe_quadratic_roots in
                   let n2 = Polysolv.solve w.quartic x2 2 ~sturm:false ~eps:0. y2 in
                   for q2 = n2 - 1 downto 0 do
                     let kk = y2.(q2) in
                     if hit (kk /. len) wv seg && kk < !best then best := kk
                   done
                 end
               end
             done
           done
         with Exit -> ());
        if !k > 0 then Stats.hit stats Stats.lathe;
        !k
      end
    end
  end

(* a top-level lathe is tried only when the ray passes its box (Trace::FindIntersection) *)
let depth (w : Scratch.t) t o d lo =
  if w.robust || Curve_hits.box_admits t.pbox o d then Curve_hits.nearest w (crossings w t ~all:false o d) lo else infinity
let hits w t id o d lo n = Curve_hits.push w (crossings w t ~all:true o d) id o d lo n

let inside t (p : Vec.t) =
  let q = Transform.inv_point t.tr p in
  let nc = ref 0 in
  if q.y >= t.height1 && q.y <= t.height2 then begin
    let r = sqrt ((q.x *. q.x) +. (q.z *. q.z)) in
    if r >= t.radius1 && r <= t.radius2 then begin
      let work = Polysolv.create () and c = Array.make 4 0. and roots = Array.make 3 0. in
      Array.iteri
        (fun i (e : segment) ->
          let be = t.bcyl.entry.(i) in
          if q.y >= t.bcyl.height.(be.h1) -. epsilon && q.y <= t.bcyl.height.(be.h2) +. epsilon then begin
            c.(0) <- e.ay;
            c.(1) <- e.by;
            c.(2) <- e.cy;
            c.(3) <- e.dy -. q.y;
            let n = Polysolv.solve work c 3 ~sturm:t.sturm ~eps:0. roots in
            for k = n - 1 downto 0 do
              let w = roots.(k) in
              if w >= 0. && w <= 1. then begin
                let k = (w *. ((w *. ((w *. e.ax) +. e.bx)) +. e.cx)) +. e.dx -. r in
                if k >= 0. then incr nc
              end
            done
          end)
        t.segs
    end
  end;
  !nc land 1 = 1

let normal t part (p : Vec.t) =
  let nseg = Array.length t.segs in
  let e = t.segs.(Curve_hits.segment ~segments:nseg part) and d1 = Curve_hits.parameter ~segments:nseg part in
  let q = Transform.inv_point t.tr p in
  let r = (q.x *. q.x) +. (q.z *. q.z) in
  let n =
    if r > epsilon then begin
      let r = sqrt r in
      let dx = (d1 *. ((3. *. e.ax *. d1) +. (2. *. e.bx))) +. e.cx in
      let dy = (d1 *. ((3. *. e.ay *. d1) +. (2. *. e.by))) +. e.cy in
      Vec.make (dy *. q.x) (-.dx *. r) (dy *. q.z)
    end
    else Vec.make 0. 1. 0.
  in
  Transform.normalize (Transform.normal t.tr n)

let uv t part (p : Vec.t) =
  let nseg = Array.length t.segs in
  let q = Transform.inv_point t.tr p in
  let v = (Curve_hits.parameter ~segments:nseg part +. Float.of_int (Curve_hits.segment ~segments:nseg part)) /. Float.of_int nseg in
  Vec.make (Sor.angle q) (if v > 1. then 1. else v) 0.

let box t = Curve_hits.revolution_box ~radius2:t.radius2 ~height1:t.height1 ~height2:t.height2
let bounds t = Transform.bounds t.tr (box t)

let traits = { Traits.default with name = "lathe"; sturm = Sturm_flag }
