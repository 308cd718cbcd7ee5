(* The surface of revolution (shape/sor.cpp, parse.cpp: Parse_Sor): the radius² about the Y axis
   a cubic of the height in each segment, through the points 1 … n−2 with the slopes the outer
   points give; capped unless open. Every rule, constant and operation order is POV-Ray's. *)

type segment = { a : float; b : float; c : float; d : float }

type t = {
  segs : segment array;
  bcyl : Bcyl.t;
  height1 : float;
  height2 : float;
  radius1 : float;
  radius2 : float;
  base_radius2 : float;
  cap_radius2 : float;
  closed : bool;
  sturm : bool;
  tr : Transform.t;
  pbox : float array;
}

include Curve_hits.Limits

let pov_box t = Curve_hits.revolution_pov_box t.tr ~radius2:t.radius2 ~height1:t.height1 ~height2:t.height2

(* Compute_Sor: segment i through points i+1 and i+2, the slopes from points i and i+3 *)
let make ~closed ~sturm (p : (float * float) array) =
  let number = Array.length p - 3 in
  let px i = fst p.(i) and py i = snd p.(i) in
  let work = Polysolv.create () in
  let exception Bad of string in
  try
    let r1 = Array.make number 0. and r2 = Array.make number 0. and h1 = Array.make number 0. and h2 = Array.make number 0. in
    let xmin = ref bound_huge and xmax = ref (-.bound_huge) and ymin = ref bound_huge and ymax = ref (-.bound_huge) in
    let segs =
      Array.init number (fun i ->
          if Float.abs (py (i + 2) -. py i) < epsilon || Float.abs (py (i + 3) -. py (i + 1)) < epsilon then
            raise (Bad "Incorrect point in surface of revolution.");
          let k0 = px (i + 1) *. px (i + 1) and k1 = px (i + 2) *. px (i + 2) in
          let k2 = (px (i + 2) -. px i) /. (py (i + 2) -. py i) in
          let k3 = (px (i + 3) -. px (i + 1)) /. (py (i + 3) -. py (i + 1)) in
          let k2 = k2 *. (2. *. px (i + 1)) and k3 = k3 *. (2. *. px (i + 2)) in
          let w1 = py (i + 1) and w2 = py (i + 2) in
          let mat =
            [| w1 *. w1 *. w1; w1 *. w1; w1; 1.;
               w2 *. w2 *. w2; w2 *. w2; w2; 1.;
               3. *. w1 *. w1; 2. *. w1; 1.; 0.;
               3. *. w2 *. w2; 2. *. w2; 1.; 0. |]
          in
          let m = match Transform.invert mat with Some m -> m | None -> raise (Bad "Singular matrix in MInvers.") in
          let row r = (k0 *. m.(4 * r)) +. (k1 *. m.((4 * r) + 1)) +. (k2 *. m.((4 * r) + 2)) +. (k3 *. m.((4 * r) + 3)) in
          let small v = if Float.abs v < epsilon then 0. else v in
          let a = small (row 0) and b = small (row 1) and c = small (row 2) and d = small (row 3) in
          let y0 = py (i + 1) and y1 = py (i + 2) in
          let x = [| px (i + 1); px (i + 2); px (i + 1); px (i + 2) |] in
          let cf = [| 3. *. a; 2. *. b; c |] and r = [| 0.; 0. |] in
          let n = Polysolv.solve work cf 2 ~sturm:false ~eps:0. r in
          for k = n - 1 downto 0 do
            if r.(k) >= y0 && r.(k) <= y1 then x.(k) <- sqrt ((r.(k) *. ((r.(k) *. ((r.(k) *. a) +. b)) +. c)) +. d)
          done;
          r1.(i) <- cmin (cmin x.(0) x.(1)) (cmin x.(2) x.(3));
          r2.(i) <- cmax (cmax x.(0) x.(1)) (cmax x.(2) x.(3));
          h1.(i) <- y0;
          h2.(i) <- y1;
          xmin := cmin !xmin r1.(i);
          xmax := cmax !xmax r2.(i);
          ymin := cmin !ymin h1.(i);
          ymax := cmax !ymax h2.(i);
          { a; b; c; d })
    in
    let radius2_at (s : segment) w = (w *. ((w *. ((s.a *. w) +. s.b)) +. s.c)) +. s.d in
    let cap = radius2_at segs.(number - 1) h2.(number - 1) and base = radius2_at segs.(0) h1.(0) in
    Ok
      {
        segs;
        bcyl = Bcyl.make r1 r2 h1 h2;
        height1 = !ymin;
        height2 = !ymax;
        radius1 = !xmin;
        radius2 = !xmax;
        base_radius2 = (if base < 0. then 0. else base);
        cap_radius2 = (if cap < 0. then 0. else cap);
        closed;
        sturm;
        tr = Transform.identity;
        pbox = [||];
      }
      |> Result.map (fun t -> { t with pbox = pov_box t })
  with Bad msg -> Error msg

let transform t m =
  let t = { t with tr = Transform.compose t.tr m } in
  { t with pbox = pov_box t }

let crossings (w : Scratch.t) t ~all (o : Vec.t) (dir : Vec.t) =
  let stats = w.stats in
  Stats.test stats Stats.sor;
  let p = Transform.inv_point t.tr o and dv = Transform.inv_direction t.tr dir in
  let len = sqrt ((dv.x *. dv.x) +. (dv.y *. dv.y) +. (dv.z *. dv.z)) in
  let s = 1. /. len in
  let dx = dv.x *. s and dy = dv.y *. s and dz = dv.z *. s in
  let px = p.x and py = p.y and pz = p.z in
  let near = Curve_hits.near_limit w in
  Stats.test stats Stats.sor_bound;
  if (dy >= 0. && py > t.height2) || (dy <= 0. && py < t.height1) || (dx >= 0. && px > t.radius2) || (dx <= 0. && px < -.t.radius2) then 0
  else begin
    let r0 = (px *. dz) -. (pz *. dx) in
    let a = (dx *. dx) +. (dz *. dz) in
    let r0 = if a > 0. then r0 /. sqrt a else r0 in
    if r0 > t.radius2 then 0
    else begin
      let k = ref 0 in
      let hit kk part = let d = kk /. len in if d > near && d < max_distance then (k := Curve_hits.add w !k d part; true) else false in
      let best = ref bound_huge in
      if t.closed && Float.abs dy > epsilon then begin
        let plane h r2 part =
          if r2 > depth_tolerance then begin
            let kk = (h -. py) /. dy in
            let u = px +. (kk *. dx) and v = pz +. (kk *. dz) in
            if (u *. u) +. (v *. v) <= r2 && hit kk part && kk < !best then best := kk
          end
        in
        plane t.height1 t.base_radius2 1;
        plane t.height2 t.cap_radius2 2
      end;
      let cnt = Bcyl.intersect w t.bcyl px py pz dx dy dz in
      if cnt > 0 || !k > 0 then Stats.hit stats Stats.sor_bound;
      let c = w.coeffs and roots = w.roots in
      (try
         for j = 0 to cnt - 1 do
           let seg = Bcyl.interval_segment w j in
           let e = t.segs.(seg) in
           (* a top-level object stops at the first interval beyond its nearest hit; a CSG member
              (IS_CHILD_OBJECT) takes them all *)
           if (not all) && Bcyl.interval_depth w j > !best then raise Exit;
           c.(0) <- e.a *. dy *. dy *. dy;
           c.(1) <- (dy *. dy *. ((3. *. e.a *. py) +. e.b)) -. a;
           c.(2) <- (dy *. ((py *. ((3. *. e.a *. py) +. (2. *. e.b))) +. e.c)) -. (2. *. ((px *. dx) +. (pz *. dz)));
           c.(3) <- (py *. ((py *. ((e.a *. py) +. e.b)) +. e.c)) +. e.d -. (px *. px) -. (pz *. pz);
           let n = Polysolv.solve w.quartic c 3 ~sturm:t.sturm ~eps:0. roots in
           let be = t.bcyl.entry.(seg) in
           let lo = t.bcyl.height.(be.h1) and hi = t.bcyl.height.(be.h2) in
           for r = n - 1 downto 0 do
             let kk = roots.(r) in
             let h = py +. (kk *. dy) in
             if h >= lo && h <= hi && hit kk (3 + seg) && kk < !best then best := kk
           done
         done
       with Exit -> ());
      if !k > 0 then Stats.hit stats Stats.sor;
      !k
    end
  end

(* a top-level sor is tried only when the ray passes its box (Trace::FindIntersection) *)
let depth (w : Scratch.t) t o d lo =
  if w.robust || Curve_hits.box_admits t.pbox o d then Curve_hits.nearest w (crossings w t ~all:false o d) lo else infinity
let hits w t id o d lo n = Curve_hits.push w (crossings w t ~all:true o d) id o d lo n

let inside t (p : Vec.t) =
  let q = Transform.inv_point t.tr p in
  q.y >= t.height1 && q.y <= t.height2
  &&
  let r0 = (q.x *. q.x) +. (q.z *. q.z) in
  r0 <= t.radius2 *. t.radius2
  &&
  let n = Array.length t.segs in
  let rec find i =
    if i >= n then false
    else
      let be = t.bcyl.entry.(i) in
      if q.y >= t.bcyl.height.(be.h1) && q.y <= t.bcyl.height.(be.h2) then
        let e = t.segs.(i) in
        r0 <= (q.y *. ((q.y *. ((q.y *. e.a) +. e.b)) +. e.c)) +. e.d
      else find (i + 1)
  in
  find 0

let normal t part (p : Vec.t) =
  let n =
    match part with
    | 1 -> Vec.make 0. (-1.) 0.
    | 2 -> Vec.make 0. 1. 0.
    | _ ->
        let q = Transform.inv_point t.tr p in
        let e = t.segs.(part - 3) in
        let k = 0.5 *. ((q.y *. ((3. *. e.a *. q.y) +. (2. *. e.b))) +. e.c) in
        Vec.make q.x (-.k) q.z
  in
  Transform.normalize (Transform.normal t.tr n)

(* the angle about Y from +x, 0 … 1 (Sor::UVCoord and Lathe::UVCoord) *)
let angle (q : Vec.t) =
  let len = (q.x *. q.x) +. (q.z *. q.z) in
  if len > epsilon then begin
    let len = sqrt len in
    let theta =
      if q.z = 0. then if q.x > 0. then 0. else Float.pi
      else
        let th = acos (q.x /. len) in
        if q.z < 0. then (2. *. Float.pi) -. th else th
    in
    theta /. (2. *. Float.pi)
  end
  else 0.

let uv t part (p : Vec.t) =
  let q = Transform.inv_point t.tr p in
  let u = angle q in
  let v =
    match part with
    | 1 -> (sqrt ((q.x *. q.x) +. (q.z *. q.z)) /. sqrt t.base_radius2) -. 1.
    | 2 -> (-.sqrt ((q.x *. q.x) +. (q.z *. q.z)) /. sqrt t.cap_radius2) +. 2.
    | _ ->
        let i = part - 3 in
        let be = t.bcyl.entry.(i) in
        let lo = t.bcyl.height.(be.h1) in
        let h = t.bcyl.height.(be.h2) -. lo in
        let per = 1. /. Float.of_int (Array.length t.segs) in
        ((q.y -. lo) /. h *. per) +. (Float.of_int i *. per)
  in
  Vec.make u v 0.

let box t = Curve_hits.revolution_box ~radius2:t.radius2 ~height1:t.height1 ~height2:t.height2
let bounds t = Transform.bounds t.tr (box t)

let traits = { Traits.default with name = "sor"; sturm = Sturm_flag }
