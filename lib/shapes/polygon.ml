(* The polygon, after POV-Ray 3.7's shape/polygon.cpp and Parse_Polygon (docs/povray-rules.md §15.7), in
   their operation order. *)

type t = { tr : Transform.t; points : float array; degenerate : bool }

let epsilon = Precision.epsilon

(* Polygon::Intersect: a depth below this, in polygon units, is no hit (DEPTH_TOLERANCE); a
   direction this close to the plane never meets it, and a point this far from the plane of the
   first three makes the polygon degenerate (ZERO_TOLERANCE) *)
let depth_tolerance = 1e-8
let zero_tolerance = 1e-10

(* SMALL_TOLERANCE: the least thickness of a polygon's box *)
let small_tolerance = 1e-3
let bound_huge = 2e10

let close (points : Vec.t array) =
  let n = Array.length points in
  let pts = Array.copy points in
  let first = ref pts.(0) and closed = ref false and i = ref 1 in
  while !i < n do
    closed := false;
    let p = !first and q = pts.(!i) in
    if Float.abs (p.x -. q.x) < epsilon && Float.abs (p.y -. q.y) < epsilon && Float.abs (p.z -. q.z) < epsilon then begin
      (* snapped exactly, so that the outline test can find the end by equality *)
      pts.(!i) <- p;
      incr i;
      if !i < n then first := pts.(!i);
      closed := true
    end;
    incr i
  done;
  if !closed then (pts, false) else (Array.append pts [| !first |], true)

let sum_sqr (v : Vec.t) = (v.x *. v.x) +. (v.y *. v.y) +. (v.z *. v.z)

(* Compute_Polygon *)
let make (points : Vec.t array) =
  let n = Array.length points in
  let o = points.(0) in
  let degenerate = ref false in
  (* u: the first point away from o *)
  let i = ref 1 and u = ref Vec.zero in
  while !i < n && (u := Vec.sub points.(!i) o; not (sum_sqr !u > epsilon)) do incr i done;
  if !i >= n then degenerate := true;
  (* v: the first later point away from o and off the line o + s·u *)
  incr i;
  let v = ref Vec.zero and w = ref Vec.zero in
  while !i < n && (v := Vec.sub points.(!i) o; w := Vec.cross !u !v; not (sum_sqr !v > epsilon && sum_sqr !w > epsilon)) do incr i done;
  if !i >= n then degenerate := true;
  let w = !w in
  let u = Vec.cross !v w in
  let v = Vec.cross w u in
  let u = Transform.normalize u and v = Transform.normalize v and w = Transform.normalize w in
  (* the inverse transform: translate by −o, then the rows u, v, w as columns (MTimesC) *)
  let a = Array.init 16 (fun k -> if k mod 5 = 0 then 1. else 0.) in
  a.(12) <- -.o.x; a.(13) <- -.o.y; a.(14) <- -.o.z;
  let b = Array.init 16 (fun k -> if k mod 5 = 0 then 1. else 0.) in
  b.(0) <- u.x; b.(4) <- u.y; b.(8) <- u.z;
  b.(1) <- v.x; b.(5) <- v.y; b.(9) <- v.z;
  b.(2) <- w.x; b.(6) <- w.y; b.(10) <- w.z;
  let tr = match Transform.of_inverse (Transform.product a b) with Some t -> t | None -> Transform.identity in
  let pts = Array.make (2 * n) 0. in
  Array.iteri
    (fun k (p : Vec.t) ->
      let x = p.x -. o.x and y = p.y -. o.y and z = p.z -. o.z in
      let d = (x *. w.x) +. (y *. w.y) +. (z *. w.z) in
      if Float.abs d > zero_tolerance then degenerate := true;
      pts.(2 * k) <- (x *. u.x) +. (y *. u.y) +. (z *. u.z);
      pts.((2 * k) + 1) <- (x *. v.x) +. (y *. v.y) +. (z *. v.z))
    points;
  { tr; points = pts; degenerate = !degenerate }

let transform p t = { p with tr = Transform.compose p.tr t }

(* Polygon::in_polygon: the even-odd crossing test of the +u ray from (tx, ty), walking the vertex
   pairs; where an edge ends on the first vertex of its sub-polygon (exactly: Parse_Polygon
   snapped it) and at least two vertices remain, the walk jumps to the next sub-polygon. *)
let[@inline] in_polygon (pts : float array) tx ty =
  let n = Array.length pts / 2 in
  let v0 = ref 0 and v1 = ref 1 and first = ref 0 in
  let yflag0 = ref (pts.(1) >= ty) and inside = ref false and i = ref 1 in
  while !i < n do
    let x0 = pts.(2 * !v0) and y0 = pts.((2 * !v0) + 1) and x1 = pts.(2 * !v1) and y1 = pts.((2 * !v1) + 1) in
    let yflag1 = y1 >= ty in
    if !yflag0 <> yflag1 && ((y1 -. ty) *. (x0 -. x1) >= (x1 -. tx) *. (y0 -. y1)) = yflag1 then inside := not !inside;
    if !i < n - 2 && x1 = pts.(2 * !first) && y1 = pts.((2 * !first) + 1) then begin
      incr i;
      v0 := !i;
      incr i;
      v1 := !i;
      yflag0 := pts.((2 * !v0) + 1) >= ty;
      first := !v0
    end
    else begin
      v0 := !v1;
      incr i;
      v1 := !i;
      yflag0 := yflag1
    end
  done;
  !inside

let intersect (stats : Stats.t) (lim : Limits.t) p (o : Vec.t) (d : Vec.t) (out : float array) =
  if p.degenerate then 0
  else begin
    Stats.test stats Stats.polygon;
    let t = p.tr in
    let px = (o.x *. t.i00) +. (o.y *. t.i10) +. (o.z *. t.i20) +. t.i30 in
    let py = (o.x *. t.i01) +. (o.y *. t.i11) +. (o.z *. t.i21) +. t.i31 in
    let pz = (o.x *. t.i02) +. (o.y *. t.i12) +. (o.z *. t.i22) +. t.i32 in
    let vx = (d.x *. t.i00) +. (d.y *. t.i10) +. (d.z *. t.i20) in
    let vy = (d.x *. t.i01) +. (d.y *. t.i11) +. (d.z *. t.i21) in
    let vz = (d.x *. t.i02) +. (d.y *. t.i12) +. (d.z *. t.i22) in
    let len = sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
    (* VInverseScaleEq: times the reciprocal *)
    let k = 1. /. len in
    let vx = vx *. k and vy = vy *. k and vz = vz *. k in
    if Float.abs vz < zero_tolerance then 0
    else begin
      let s = -.pz /. vz in
      (* the robust mode's limits take every positive depth *)
      let near = Float.min depth_tolerance lim.near in
      if s < near || s > lim.far then 0
      else if in_polygon p.points (px +. (s *. vx)) (py +. (s *. vy)) then begin
        Stats.hit stats Stats.polygon;
        out.(0) <- s /. len;
        1
      end
      else 0
    end
  end

let normal p (_ : Vec.t) = Transform.normalize (Transform.normal p.tr (Vec.make 0. 0. 1.))
let inside (_ : t) (_ : Vec.t) = false

(* the points mapped to world space: their extent (min x, y, z, max x, y, z), as Compute_BBox
   gathers it *)
let extent p =
  let lo = Array.make 3 bound_huge and hi = Array.make 3 (-.bound_huge) in
  for k = 0 to (Array.length p.points / 2) - 1 do
    let q = Transform.point p.tr (Vec.make p.points.(2 * k) p.points.((2 * k) + 1) 0.) in
    let c = [| q.x; q.y; q.z |] in
    for a = 0 to 2 do
      if c.(a) < lo.(a) then lo.(a) <- c.(a);
      if hi.(a) < c.(a) then hi.(a) <- c.(a)
    done
  done;
  (lo, hi)

let pov_box p =
  if p.degenerate then [||]
  else
    let lo, hi = extent p in
    let f32 = Precision.f32 in
    let b = [| f32 lo.(0); f32 lo.(1); f32 lo.(2); f32 (hi.(0) -. lo.(0)); f32 (hi.(1) -. lo.(1)); f32 (hi.(2) -. lo.(2)) |] in
    for a = 0 to 2 do
      if Float.abs b.(a + 3) < small_tolerance then begin
        b.(a) <- f32 (b.(a) -. small_tolerance);
        b.(a + 3) <- f32 (b.(a + 3) +. (2.0 *. small_tolerance))
      end
    done;
    b

let bounds p =
  if p.degenerate then None
  else
    let lo, hi = extent p in
    let thin a = hi.(a) -. lo.(a) < small_tolerance in
    Some (Array.init 6 (fun k -> if k < 3 then (if thin k then lo.(k) -. small_tolerance else lo.(k)) else if thin (k - 3) then hi.(k - 3) +. small_tolerance else hi.(k - 3)))

let magnitude p = match bounds p with None -> 0. | Some b -> Array.fold_left (fun m v -> Float.max m (Float.abs v)) 0. b

let depth (w : Scratch.t) p o d lo = Scratch.nearest_depth w (intersect w.stats w.lim p o d w.crossings) lo

let hits (w : Scratch.t) p id o d lo n =
  let k = intersect w.stats w.lim p o d w.crossings in
  if k > 0 then Scratch.push_ray w n lo w.crossings.(0) (-1) id o d else n

let traits = { Traits.default with name = "polygon"; inverse_flag = false }
