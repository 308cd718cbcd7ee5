(* Triangles as POV-Ray sets them up (docs/povray-rules.md §2.4, §2.5): a unit normal and plane distance,
   the dominant axis of the normal for a 2-D inside test, vertices 1 and 2 swapped once so that the
   winding in that projection is consistent, and for smooth triangles the vector Perp and axis used
   to interpolate the vertex normals. *)

type t = {
  nx : float; ny : float; nz : float;
  dist : float;  (* −N·P1 *)
  x1 : float; y1 : float; z1 : float;
  x2 : float; y2 : float; z2 : float;
  x3 : float; y3 : float; z3 : float;
  axis : float;  (* dominant axis of the normal: 0, 1 or 2 *)
  (* smooth triangles only *)
  px : float; py : float; pz : float;  (* Perp, scaled so that u = (P − P1)·Perp *)
  vaxis : float;  (* dominant axis of P3 − P2 *)
  m1x : float; m1y : float; m1z : float;
  m2x : float; m2y : float; m2z : float;
  m3x : float; m3y : float; m3z : float;
}

(* POV-Ray's max3_coordinate: on ties the later axis wins. *)
let max3_coordinate x y z = if x > y then if x > z then 0 else 2 else if y > z then 1 else 2

let coord (v : Vec.t) a = match a with 0 -> v.x | 1 -> v.y | _ -> v.z

(* Whether P1 and P2 must be swapped for a consistent winding in the projection along [axis]. *)
let needs_swap axis (p1 : Vec.t) (p2 : Vec.t) (p3 : Vec.t) =
  let u, w = match axis with 0 -> (1, 2) | 1 -> (0, 2) | _ -> (0, 1) in
  let c = coord in
  ((c p2 u -. c p3 u) *. (c p2 w -. c p1 w)) < ((c p2 w -. c p3 w) *. (c p2 u -. c p1 u))

(* Perp and the interpolation axis, computed from the (swapped) corners. [round] is applied to
   Perp where the storage is single precision (meshes). *)
let smooth_setup ~round (p1 : Vec.t) (p2 : Vec.t) (p3 : Vec.t) =
  let p32 = Vec.sub p3 p2 in
  let vaxis = max3_coordinate (Float.abs p32.x) (Float.abs p32.y) (Float.abs p32.z) in
  let t1 = Vec.normalize (Vec.sub p2 p3) in
  let t2 = Vec.sub p1 p3 in
  let proj = Vec.dot t2 t1 in
  let t1 = Vec.scale proj t1 in
  let perp = round (Vec.normalize (Vec.sub t1 t2)) in
  let uden = -.Vec.dot t2 perp in
  (* VInverseScaleEq: times the reciprocal *)
  (round (Vec.scale (1. /. uden) perp), vaxis)

let zero = Vec.zero

let make_record (n : Vec.t) dist (p1 : Vec.t) (p2 : Vec.t) (p3 : Vec.t) axis (perp : Vec.t) vaxis (m1 : Vec.t) (m2 : Vec.t) (m3 : Vec.t) =
  {
    nx = n.x; ny = n.y; nz = n.z; dist;
    x1 = p1.x; y1 = p1.y; z1 = p1.z; x2 = p2.x; y2 = p2.y; z2 = p2.z; x3 = p3.x; y3 = p3.y; z3 = p3.z;
    axis = float_of_int axis;
    px = perp.x; py = perp.y; pz = perp.z; vaxis = float_of_int vaxis;
    m1x = m1.x; m1y = m1.y; m1z = m1.z; m2x = m2.x; m2y = m2.y; m2z = m2.z; m3x = m3.x; m3y = m3.y; m3z = m3.z;
  }

(* §2.4: N = normalize((P1 − P2) × (P3 − P2)); None for a degenerate (zero-area) triangle. *)
let flat p1 p2 p3 =
  let n = Vec.cross (Vec.sub p1 p2) (Vec.sub p3 p2) in
  let len = Vec.length n in
  if len = 0. then None
  else
    let n = Vec.scale (1. /. len) n in
    let dist = -.Vec.dot n p1 in
    let axis = max3_coordinate (Float.abs n.x) (Float.abs n.y) (Float.abs n.z) in
    let p1, p2 = if needs_swap axis p1 p2 p3 then (p2, p1) else (p1, p2) in
    Some (make_record n dist p1 p2 p3 axis zero 0 zero zero zero)

(* §2.5: `None` when degenerate, [Error ()] when the vertex normals straddle the face (POV-Ray hides
   such a standalone triangle). The vertex normals are normalised first. *)
let smooth p1 n1 p2 n2 p3 n3 =
  let n = Vec.cross (Vec.sub p1 p2) (Vec.sub p3 p2) in
  let len = Vec.length n in
  if len = 0. then None
  else
    let n = Vec.scale (1. /. len) n in
    let dist = -.Vec.dot n p1 in
    let axis = max3_coordinate (Float.abs n.x) (Float.abs n.y) (Float.abs n.z) in
    let p1, p2, n1, n2 = if needs_swap axis p1 p2 p3 then (p2, p1, n2, n1) else (p1, p2, n1, n2) in
    let perp, vaxis = smooth_setup ~round:(fun v -> v) p1 p2 p3 in
    let a = Vec.dot n n1 and b = Vec.dot n n2 and c = Vec.dot n n3 in
    if (a < 0. && b < 0. && c < 0.) || (a > 0. && b > 0. && c > 0.) then
      Some (Ok (make_record n dist p1 p2 p3 axis perp vaxis n1 n2 n3))
    else Some (Error ())

(* §2.4: the depth of the hit within [lim], or infinity. *)
let[@inline] intersect_within (lim : Limits.t) t (o : Vec.t) (d : Vec.t) =
  let ndd = (t.nx *. d.x) +. (t.ny *. d.y) +. (t.nz *. d.z) in
  if Float.abs ndd < 1e-10 then infinity
  else
    let ndo = (t.nx *. o.x) +. (t.ny *. o.y) +. (t.nz *. o.z) in
    let depth = -.(t.dist +. ndo) /. ndd in
    if depth < lim.near || depth > lim.far then infinity
    else
      let inside a1 b1 a2 b2 a3 b3 s u =
        not
          ((a2 -. s) *. (b2 -. b1) < (b2 -. u) *. (a2 -. a1)
          || (a3 -. s) *. (b3 -. b2) < (b3 -. u) *. (a3 -. a2)
          || (a1 -. s) *. (b1 -. b3) < (b1 -. u) *. (a1 -. a3))
      in
      let ok =
        if t.axis = 0. then inside t.y1 t.z1 t.y2 t.z2 t.y3 t.z3 (o.y +. (depth *. d.y)) (o.z +. (depth *. d.z))
        else if t.axis = 1. then inside t.x1 t.z1 t.x2 t.z2 t.x3 t.z3 (o.x +. (depth *. d.x)) (o.z +. (depth *. d.z))
        else inside t.x1 t.y1 t.x2 t.y2 t.x3 t.y3 (o.x +. (depth *. d.x)) (o.y +. (depth *. d.y))
      in
      if ok then depth else infinity

let[@inline] intersect t o d = intersect_within Limits.pov t o d

(* §2.5: the interpolated normal at [p] (normalised), from the vertex normals. *)
let smooth_normal t (p : Vec.t) =
  let dx = p.x -. t.x1 and dy = p.y -. t.y1 and dz = p.z -. t.z1 in
  let u = (dx *. t.px) +. (dy *. t.py) +. (dz *. t.pz) in
  if u < 1e-10 then Vec.make t.m1x t.m1y t.m1z
  else
    let pa, k1, k2, k3 =
      if t.vaxis = 0. then (dx, t.x1, t.x2, t.x3) else if t.vaxis = 1. then (dy, t.y1, t.y2, t.y3) else (dz, t.z1, t.z2, t.z3)
    in
    let v = ((pa /. u) +. k1 -. k2) /. (k3 -. k2) in
    let f a1 a2 a3 = a1 +. (u *. (a2 -. a1 +. (v *. (a3 -. a2)))) in
    Vec.normalize (Vec.make (f t.m1x t.m2x t.m3x) (f t.m1y t.m2y t.m3y) (f t.m1z t.m2z t.m3z))

let bounds t =
  [| Float.min t.x1 (Float.min t.x2 t.x3); Float.min t.y1 (Float.min t.y2 t.y3); Float.min t.z1 (Float.min t.z2 t.z3);
     Float.max t.x1 (Float.max t.x2 t.x3); Float.max t.y1 (Float.max t.y2 t.y3); Float.max t.z1 (Float.max t.z2 t.z3) |]

let depth (w : Scratch.t) t o d lo =
  let stats = w.stats in
  Stats.test stats Stats.triangle;
  let depth = intersect_within w.lim t o d in
  if depth >= lo && depth < infinity then (Stats.hit stats Stats.triangle; depth) else infinity

let hits w t id o d lo n =
  let depth = depth w t o d lo in
  if depth < infinity then Scratch.push_ray w n lo depth (-1) id o d else n

let flat_normal t = Vec.make t.nx t.ny t.nz

let pov_box t =
  let e = Precision.epsilon in
  let mn a b c = Float.min a (Float.min b c) -. e and mx a b c = Float.max a (Float.max b c) +. e in
  Pov_box.of_min_max [| mn t.x1 t.x2 t.x3; mn t.y1 t.y2 t.y3; mn t.z1 t.z2 t.z3 |] [| mx t.x1 t.x2 t.x3; mx t.y1 t.y2 t.y3; mx t.z1 t.z2 t.z3 |]

let traits = { Traits.default with name = "triangle"; costly = false; box_test_free = true; patch = true }
let smooth_traits = { traits with name = "smooth_triangle"; scale_by_matrix = true }
