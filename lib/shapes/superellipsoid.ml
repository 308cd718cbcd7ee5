(* The superellipsoid, after POV-Ray 3.7's shape/super.cpp: its own root search along the ray
   (the ray cut by the planes that split the shape into pieces where it is monotonic, then a
   secant-and-bisection search in each piece that changes sign), with every constant and every
   operation in POV-Ray's order. *)

type t = { ex : float; ey : float; ez : float; tr : Transform.t }

let depth_tolerance = 1e-4 (* DEPTH_TOLERANCE: world depths at or below it are no hit *)
let zero_tolerance = 1e-10 (* a value this close to 0 is on the surface *)
let min_value = -1.01 (* the unit box the search starts from, a little larger *)
let max_value = 1.01
let max_iterations = 20
let epsilon = Precision.epsilon
let bound_huge = 2e10
let max_distance = 1e7

(* Parse_Superellipsoid: <e, n> become the powers 2/e, e/n, 2/n *)
let make e n = { ex = 2.0 /. e; ey = e /. n; ez = 2.0 /. n; tr = Transform.identity }
let transform s m = { s with tr = Transform.compose s.tr m }

(* power: x^e, with the small integer powers multiplied out as POV-Ray does *)
let power x e =
  let i = Float.to_int e in
  if e = Float.of_int i then
    match i with
    | 0 -> 1.0
    | 1 -> x
    | 2 -> x *. x
    | 3 -> x *. x *. x
    | 4 -> let b = x *. x in b *. b
    | 5 -> let b = x *. x in b *. b *. x
    | 6 -> let b = x *. x in b *. b *. b
    | _ -> Float.pow x e
  else Float.pow x e

(* evaluate_g: (x^e + y^e)^(1/e), the larger of x and y taken out of the sum *)
let evaluate_g x y e =
  if x > y then
    let g = 1. +. power (y /. x) e in
    let g = if g <> 1. then power g (1. /. e) else g in
    g *. x
  else if y <> 0. then
    let g = 1. +. power (x /. y) e in
    let g = if g <> 1. then power g (1. /. e) else g in
    g *. y
  else 0.

(* evaluate_superellipsoid: negative inside, 0 on the surface *)
let value s x y z = evaluate_g (evaluate_g (Float.abs x) (Float.abs y) s.ex) (Float.abs z) s.ez -. 1.

(* intersect_box: the ray's entry and exit of the box ±1.01, each axis in POV-Ray's order of
   tests; None when it misses *)
let intersect_box px py pz dx dy dz =
  let exception Miss in
  try
    let dmin, dmax =
      if Float.abs dx > epsilon then begin
        let dmin, dmax =
          if dx > epsilon then begin
            let dmin = (min_value -. px) /. dx and dmax = (max_value -. px) /. dx in
            if dmax < epsilon then raise Miss;
            (dmin, dmax)
          end
          else begin
            let dmax = (min_value -. px) /. dx in
            if dmax < epsilon then raise Miss;
            ((max_value -. px) /. dx, dmax)
          end
        in
        if dmin > dmax then raise Miss;
        (dmin, dmax)
      end
      else if px < min_value || px > max_value then raise Miss
      else (-.bound_huge, bound_huge)
    in
    let slab (dmin, dmax) p d =
      if Float.abs d > epsilon then begin
        let tmin, tmax =
          if d > epsilon then ((min_value -. p) /. d, (max_value -. p) /. d) else ((max_value -. p) /. d, (min_value -. p) /. d)
        in
        if tmax < dmax then begin
          if tmax < epsilon then raise Miss;
          if tmin > dmin then begin
            if tmin > tmax then raise Miss;
            (tmin, tmax)
          end
          else begin
            if dmin > tmax then raise Miss;
            (dmin, tmax)
          end
        end
        else if tmin > dmin then begin
          if tmin > dmax then raise Miss;
          (tmin, dmax)
        end
        else (dmin, dmax)
      end
      else if p < min_value || p > max_value then raise Miss
      else (dmin, dmax)
    in
    Some (slab (slab (dmin, dmax) py dy) pz dz)
  with Miss -> None

(* the planes cutting the shape into pieces: x = ±y, x = ±z, y = ±z, x = 0, y = 0, z = 0 *)
let planes = [| (1., 1., 0.); (1., -1., 0.); (1., 0., 1.); (1., 0., -1.); (0., 1., 1.); (0., 1., -1.); (1., 0., 0.); (0., 1., 0.); (0., 0., 1.) |]

(* find_ray_plane_points: the depths in [mindist, maxdist] (widened by EPSILON of its length) at
   which the ray crosses the planes, added after the first [cnt] of [dists], all sorted *)
let ray_plane_points px py pz dx dy dz cnt dists mindist maxdist =
  let t = epsilon *. (maxdist -. mindist) in
  let mindist = mindist -. t and maxdist = maxdist +. t in
  let cnt = ref cnt in
  Array.iter
    (fun (a, b, c) ->
      let d = (dx *. a) +. (dy *. b) +. (dz *. c) in
      if not (Float.abs d < epsilon) then begin
        let t = (0. -. ((px *. a) +. (py *. b) +. (pz *. c))) /. d in
        if t >= mindist && t <= maxdist then begin
          dists.(!cnt) <- t;
          incr cnt
        end
      end)
    planes;
  let sorted = Array.sub dists 0 !cnt in
  Array.stable_sort Float.compare sorted;
  Array.blit sorted 0 dists 0 !cnt;
  !cnt

(* solve_hit1: the point between P0 and P1 (values v0, v1 of opposite signs) where the value
   vanishes, by the better of a secant step and a bisection step each time *)
let solve_hit1 s v0 (p0 : Vec.t) v1 (p1 : Vec.t) =
  let rec loop i v0 (p0 : Vec.t) v1 (p1 : Vec.t) =
    if i = max_iterations then if Float.abs v0 < Float.abs v1 then p0 else p1
    else if Float.abs v0 < zero_tolerance then p0
    else if Float.abs v1 < zero_tolerance then p1
    else begin
      let x = Float.abs v0 /. Float.abs (v1 -. v0) in
      let p2 = Vec.make (p0.x +. (x *. (p1.x -. p0.x))) (p0.y +. (x *. (p1.y -. p0.y))) (p0.z +. (x *. (p1.z -. p0.z))) in
      let v2 = value s p2.x p2.y p2.z in
      let p3 = Vec.make (p0.x +. (0.5 *. (p1.x -. p0.x))) (p0.y +. (0.5 *. (p1.y -. p0.y))) (p0.z +. (0.5 *. (p1.z -. p0.z))) in
      let v3 = value s p3.x p3.y p3.z in
      if v2 *. v3 < 0.0 then loop (i + 1) v2 p2 v3 p3
      else if Float.abs v2 < Float.abs v3 then
        if v0 *. v2 < 0. then loop (i + 1) v0 p0 v2 p2 else loop (i + 1) v2 p2 v1 p1
      else if v0 *. v3 < 0. then loop (i + 1) v0 p0 v3 p3
      else loop (i + 1) v3 p3 v1 p1
    end
  in
  loop 0 v0 p0 v1 p1

let dist_from (p : Vec.t) (q : Vec.t) =
  let x = q.x -. p.x and y = q.y -. p.y and z = q.z -. p.z in
  sqrt ((x *. x) +. (y *. y) +. (z *. z))

let on_ray (p : Vec.t) t (d : Vec.t) = Vec.make (p.x +. (t *. d.x)) (p.y +. (t *. d.y)) (p.z +. (t *. d.z))

(* check_hit2: between two samples of the same sign the ray may still dip through the surface;
   secant steps from t0 towards t1 look for a sign change. Some depth (in superellipsoid
   space) when one is found. *)
let check_hit2 s (p : Vec.t) (d : Vec.t) t0 (p0 : Vec.t) v0 t1 =
  let maxdelta = t1 -. t0 in
  let rec loop i dt0 dt1 v0 p0 =
    if not (dt0 < t1 && i < max_iterations) then None
    else begin
      let p1 = on_ray p dt1 d in
      let v1 = value s p1.x p1.y p1.z in
      if v0 *. v1 < 0. then Some (dist_from p (solve_hit1 s v0 p0 v1 p1))
      else if Float.abs v1 < zero_tolerance then Some dt1
      else if (v0 > 0.0 && v1 > v0) || (v0 < 0.0 && v1 < v0) then None
      else if v1 = v0 then None
      else
        let deltat = v1 *. (dt1 -. dt0) /. (v1 -. v0) in
        if Float.abs deltat > maxdelta then None else loop (i + 1) dt1 (dt1 -. deltat) v1 p0
    end
  in
  loop 0 t0 (t0 +. (0.0001 *. (t1 -. t0))) v0 p0

(* Superellipsoid::Intersect: the world depths accepted by insert_hit (beyond [near], below 1e7),
   in the order found, written into [out] (room for 11); a shape alone stops at the first
   ([all] false), a CSG member goes on (IS_CHILD_OBJECT) *)
let intersect s ~near ~all (o : Vec.t) (d : Vec.t) (out : float array) =
  let m = s.tr in
  let p = Transform.inv_point m o in
  let dv = Transform.inv_direction m d in
  let len = sqrt ((dv.x *. dv.x) +. (dv.y *. dv.y) +. (dv.z *. dv.z)) in
  let k = 1.0 /. len in
  let dv = Vec.make (dv.x *. k) (dv.y *. k) (dv.z *. k) in
  match intersect_box p.x p.y p.z dv.x dv.y dv.z with
  | None -> 0
  | Some (_, t2) when t2 < depth_tolerance -> 0
  | Some (t1, t2) ->
      let t1 = if t1 < depth_tolerance then depth_tolerance else t1 in
      let dists = Array.make 11 0. in
      dists.(0) <- t1;
      dists.(1) <- t2;
      let cnt = ray_plane_points p.x p.y p.z dv.x dv.y dv.z 2 dists t1 t2 in
      if cnt <= 1 then 0
      else begin
        let n = ref 0 in
        let exception Stop in
        (* insert_hit: whether the depth was kept; a shape alone stops at its first *)
        let insert t =
          let depth = t /. len in
          if depth > near && depth < max_distance then begin
            out.(!n) <- depth;
            incr n;
            if not all then raise Stop;
            true
          end
          else false
        in
        (try
           let p0 = on_ray p dists.(0) dv in
           let v0 = value s p0.x p0.y p0.z in
           if Float.abs v0 < zero_tolerance then ignore (insert dists.(0));
           let rec loop i v0 p0 =
             if i < cnt then begin
               let p1 = on_ray p dists.(i) dv in
               let v1 = value s p1.x p1.y p1.z in
               let continue =
                 if Float.abs v1 < zero_tolerance then (ignore (insert dists.(i)); true)
                 else if v0 *. v1 < 0.0 then (ignore (insert (dist_from p (solve_hit1 s v0 p0 v1 p1))); true)
                 else
                   match check_hit2 s p dv dists.(i - 1) p0 v0 dists.(i) with
                   | Some t -> insert t
                   | None -> true
               in
               if continue then loop (i + 1) v1 p1
             end
           in
           loop 1 v0 p0
         with Stop -> ());
        !n
      end

(* Superellipsoid::Inside: the value below EPSILON *)
let inside s (q : Vec.t) =
  let p = Transform.inv_point s.tr q in
  value s p.x p.y p.z < epsilon

(* Superellipsoid::Normal, in superellipsoid space then by the inverse transpose, normalised.
   Where x = y = 0 POV-Ray reads an unset ratio; it is taken as 0 here. *)
let normal s (q : Vec.t) =
  let p = Transform.inv_point s.tr q in
  let x = p.x and y = p.y and z = p.z in
  let z2n, z = if z <> 0. then let z2n = power (Float.abs z) s.ez in (z2n, z2n /. z) else (0., z) in
  let r, x, y =
    if Float.abs x > Float.abs y then
      let r = power (Float.abs (y /. x)) s.ex in
      (r, (1. -. z2n) /. x, if y <> 0. then (1. -. z2n) *. r /. y else 0.)
    else if y <> 0. then
      let r = power (Float.abs (x /. y)) s.ex in
      (r, (if x <> 0. then (1. -. z2n) *. r /. x else 0.), (1. -. z2n) /. y)
    else (0., x, y)
  in
  let z = if z <> 0. then z *. (1. +. r) else z in
  Transform.normalize (Transform.normal s.tr (Vec.make x y z))

(* Make_BBox(−1.0001, −1.0001, −1.0001, 2.0002, 2.0002, 2.0002) before the transform *)
let box = [| -1.0001; -1.0001; -1.0001; 1.0001; 1.0001; 1.0001 |]
let bounds s = Transform.bounds s.tr box

let pov_box s =
  let f = Precision.f32 in
  Pov_box.mapped s.tr [| f (-1.0001); f (-1.0001); f (-1.0001); f 2.0002; f 2.0002; f 2.0002 |]

let near_limit (w : Scratch.t) = if w.robust then 0. else depth_tolerance

let counted (w : Scratch.t) s ~all o d out =
  let st = w.stats in
  Stats.test st Stats.superellipsoid;
  let n = intersect s ~near:(near_limit w) ~all o d out in
  if n > 0 then Stats.hit st Stats.superellipsoid;
  n

(* alone, the shape pushes only the first hit it finds: that is the only depth POV-Ray's search
   sees, kept when at least [lo] (a shadow ray's first hit at its own surface, below the shadow
   tolerance, hides the far wall) *)
let depth (w : Scratch.t) s o d lo =
  let out = w.crossings in
  let n = counted w s ~all:false o d out in
  if n > 0 && out.(0) >= lo then out.(0) else infinity

let hits (w : Scratch.t) s id o d lo n =
  let out = Array.make 11 0. in
  let k = counted w s ~all:true o d out in
  let n = ref n in
  for i = 0 to k - 1 do
    n := Scratch.push_ray w !n lo out.(i) (-1) id o d
  done;
  !n

let traits = { Traits.default with name = "superellipsoid" }
