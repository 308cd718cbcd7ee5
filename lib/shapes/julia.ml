(* The julia fractal: POV-Ray's shape/fractal.cpp, math/quatern.cpp and math/hcmplx.cpp. The 3-D
   slice of a 4-D Julia set, marched along the ray by a distance estimate, the crossing polished by
   bisection, the normal from the derivative of the iteration. *)

type algebra = Quaternion | Hypercomplex
type func = Sqr | Cube | Reciprocal | Func of Julia_algebra.func

type t = {
  p0 : float;
  p1 : float;
  p2 : float;
  p3 : float;
  s0 : float;
  s1 : float;
  s2 : float;
  s3 : float;
  slice_dist : float;
  iterations : int;
  precision : float;
  algebra : algebra;
  func : func;
  ex : float;
  ey : float;
  inverted : bool;
  trans : Transform.t option;
  radius : float;
  radius_sq : float;
  exit_value : float;
}

(* fractal.cpp's Fractal_Tolerance, and hcmplx.cpp's own, with which a step toward the surface is
   told from one along it *)
let tolerance = 1e-7
let hcmplx_tolerance = 1e-8

(* Compute_BBox: the radius of the bounding sphere and the escape value; it clears the inverted
   flag, and runs after parsing and after every transform *)
let set_up f =
  let r, exit_value =
    match f.algebra with
    | Quaternion ->
        let r = 1.0 +. sqrt ((f.p0 *. f.p0) +. (f.p1 *. f.p1) +. (f.p2 *. f.p2) +. (f.p3 *. f.p3)) in
        let r = r +. tolerance in
        let r = if r > 2.0 then 2.0 else r in
        (r, (r *. r) +. tolerance)
    | Hypercomplex -> (4.0, 16.0)
  in
  { f with radius = r; radius_sq = r *. r; exit_value; inverted = false }

let make ~parm ~slice ~slice_dist ~iterations ~precision ~algebra ~func ~exponent:(ex, ey) =
  set_up
    {
      p0 = parm.(0);
      p1 = parm.(1);
      p2 = parm.(2);
      p3 = parm.(3);
      s0 = slice.(0);
      s1 = slice.(1);
      s2 = slice.(2);
      s3 = slice.(3);
      slice_dist;
      iterations;
      precision;
      algebra;
      func;
      ex;
      ey;
      inverted = false;
      trans = None;
      radius = 0.;
      radius_sq = 0.;
      exit_value = 0.;
    }

let supported algebra func =
  match (algebra, func) with Quaternion, (Sqr | Cube) | Hypercomplex, _ -> true | Quaternion, (Reciprocal | Func _) -> false

let transform f m =
  let trans = match f.trans with None -> Transform.compose Transform.identity m | Some t -> Transform.compose t m in
  set_up { f with trans = Some trans }

let invert f = { f with inverted = not f.inverted }

(* ---------------------------------------------------------------------------------------------- *)
(* The iteration stack: (x, y, z, w) of every iterate, 4 floats each, in the worker's scratch *)

(* [g]'s room, grown to hold [f]'s iterations *)
let room (g : Scratch.growable) f =
  let need = 4 * (f.iterations + 1) in
  if Array.length g.room < need then begin
    let bigger = Scratch.big_floats need in
    Array.blit g.room 0 bigger 0 (Array.length g.room);
    g.room <- bigger
  end;
  g.room

let stack (w : Scratch.t) f = room w.fractal_stack f

(* The stack of [inside] and [normal], which have no worker's scratch: one for the process, grown
   to the most iterations seen, as POV-Ray keeps one per thread (Allocate_Iteration_Stack). A
   stack made for every call would be 4 × max_iteration floats each time: 96 MB for 3,000,000
   iterations, which the renderer's relaxed collector would not free before the address space ran
   out. Neither function calls the other while it iterates. *)
let spare : Scratch.growable = { room = [||] }

let[@inline] slice_w f x y z = (f.slice_dist -. (f.s0 *. x) -. (f.s1 *. y) -. (f.s2 *. z)) /. f.s3

let[@inline] start st x y z w =
  st.(0) <- x;
  st.(1) <- y;
  st.(2) <- z;
  st.(3) <- w

let[@inline] store st i x y z w =
  let j = 4 * i in
  st.(j) <- x;
  st.(j + 1) <- y;
  st.(j + 2) <- z;
  st.(j + 3) <- w

(* one step of each map, from (x, y, z, w) to the next iterate, c added *)
let step f x y z w =
  match (f.algebra, f.func) with
  | Quaternion, Cube ->
      let d = (y *. y) +. (z *. z) +. (w *. w) and x2 = x *. x in
      let tmp = (3.0 *. x2) -. d in
      ((x *. (x2 -. (3.0 *. d))) +. f.p0, (y *. tmp) +. f.p1, (z *. tmp) +. f.p2, (w *. tmp) +. f.p3)
  | Quaternion, (Sqr | Reciprocal | Func _) ->
      let d = (y *. y) +. (z *. z) +. (w *. w) and x2 = x *. x in
      let x' = x *. 2.0 in
      (x2 -. d +. f.p0, (x' *. y) +. f.p1, (x' *. z) +. f.p2, (x' *. w) +. f.p3)
  | Hypercomplex, Sqr ->
      let yz = (y *. y) +. (z *. z) and xw = (x *. x) +. (w *. w) in
      (xw -. yz +. f.p0, (2.0 *. ((x *. y) -. (z *. w))) +. f.p1, (2.0 *. ((x *. z) -. (w *. y))) +. f.p2, (2.0 *. ((x *. w) +. (y *. z))) +. f.p3)
  | Hypercomplex, Cube ->
      let a, b, c, e = Julia_algebra.hsqr x y z w in
      (a +. f.p0, b +. f.p1, c +. f.p2, e +. f.p3)
  | Hypercomplex, Reciprocal ->
      (* a zero determinant leaves POV-Ray's outputs unwritten: 0 here *)
      let a, b, c, e = match Julia_algebra.hreciprocal x y z w with Some r -> r | None -> (0., 0., 0., 0.) in
      (a +. f.p0, b +. f.p1, c +. f.p2, e +. f.p3)
  | Hypercomplex, Func g ->
      let a, b, c, e = Julia_algebra.hfunc g ~ex:f.ex ~ey:f.ey x y z w in
      (a +. f.p0, b +. f.p1, c +. f.p2, e +. f.p3)

(* the squared norm tested against the escape value: the quaternion maps sum y² + z² + w² first,
   the hypercomplex square (x² + w²) + (y² + z²), the others x² + y² + z² + w² *)
let[@inline] norm f x y z w =
  match (f.algebra, f.func) with
  | Quaternion, _ -> (y *. y) +. (z *. z) +. (w *. w) +. (x *. x)
  | Hypercomplex, Sqr -> ((x *. x) +. (w *. w)) +. ((y *. y) +. (z *. z))
  | Hypercomplex, (Cube | Reciprocal | Func _) -> (x *. x) +. (y *. y) +. (z *. z) +. (w *. w)

(* Iterate from [st]'s first entry; the escape index (the i whose norm exceeded the escape value,
   its norm in [escaped_norm]) or 0 when the point stays for every iteration. *)
let run f st =
  let x = ref st.(0) and y = ref st.(1) and z = ref st.(2) and w = ref st.(3) in
  let escape = ref 0 and i = ref 1 and nrm = ref 0. in
  while !escape = 0 && !i <= f.iterations do
    let n = norm f !x !y !z !w in
    if n > f.exit_value then begin
      escape := !i;
      nrm := n
    end
    else begin
      let a, b, c, e = step f !x !y !z !w in
      store st !i a b c e;
      x := a;
      y := b;
      z := c;
      w := e;
      incr i
    end
  done;
  (!escape, !nrm)

let start_at f st x y z =
  let w = slice_w f x y z in
  start st x y z w

(* Iteration: whether the point stays in the set. The function maps start from (x, y, y, w) with
   w from that y, as Iteration_HCompl_Func reads the point's y for its z. *)
let iterate f st x y z =
  (match (f.algebra, f.func) with Hypercomplex, Func _ -> start_at f st x y y | _ -> start_at f st x y z);
  fst (run f st) = 0

(* ---------------------------------------------------------------------------------------------- *)
(* Normals: the derivative of the map carried along the iterates of the stack *)

let g st i c = st.((4 * i) + c)

let quaternion_normal f st n_max =
  let n11 = ref 1.0 and n12 = ref 0.0 and n13 = ref 0.0 and n14 = ref 0.0 in
  let n21 = ref 0.0 and n22 = ref 1.0 and n23 = ref 0.0 and n24 = ref 0.0 in
  let n31 = ref 0.0 and n32 = ref 0.0 and n33 = ref 1.0 and n34 = ref 0.0 in
  let cube = match f.func with Cube -> true | Sqr | Reciprocal | Func _ -> false in
  (* step i carries the derivative through iterate i − 1 *)
  for i = 1 to n_max do
    let x = g st (i - 1) 0 and y = g st (i - 1) 1 and z = g st (i - 1) 2 and w = g st (i - 1) 3 in
    if cube then begin
      let tmp = (y *. y) +. (z *. z) +. (w *. w) in
      let x2 = x *. x in
      let x3 = x2 -. tmp and x4 = (3.0 *. x2) -. tmp in
      let deriv n1 n2 n3 n4 =
        let dtmp = 2.0 *. ((!n2 *. y) +. (!n3 *. z) +. (!n4 *. w)) in
        let dtmp2 = (6.0 *. x *. !n1) -. dtmp in
        n1 := ((!n1 *. x3) -. (x *. dtmp)) *. 3.0;
        n2 := (!n2 *. x4) +. (y *. dtmp2);
        n3 := (!n3 *. x4) +. (z *. dtmp2);
        n4 := (!n4 *. x4) +. (w *. dtmp2)
      in
      deriv n11 n12 n13 n14;
      deriv n21 n22 n23 n24;
      deriv n31 n32 n33 n34
    end
    else begin
      let deriv n1 n2 n3 n4 =
        let tmp = (!n1 *. x) -. (!n2 *. y) -. (!n3 *. z) -. (!n4 *. w) in
        n2 := (!n1 *. y) +. (x *. !n2);
        n3 := (!n1 *. z) +. (x *. !n3);
        n4 := (!n1 *. w) +. (x *. !n4);
        n1 := tmp
      in
      deriv n11 n12 n13 n14;
      deriv n21 n22 n23 n24;
      deriv n31 n32 n33 n34
    end
  done;
  let x = g st n_max 0 and y = g st n_max 1 and z = g st n_max 2 and w = g st n_max 3 in
  Vec.make
    ((!n11 *. x) +. (!n12 *. y) +. (!n13 *. z) +. (!n14 *. w))
    ((!n21 *. x) +. (!n22 *. y) +. (!n23 *. z) +. (!n24 *. w))
    ((!n31 *. x) +. (!n32 *. y) +. (!n33 *. z) +. (!n34 *. w))

(* Normal_Calc_HCompl and its kin: the product of the derivatives (for the function maps, of the
   function itself, as POV-Ray has it) over iterates 1 … n_max − 1, then the last iterate *)
let hypercomplex_normal f st n_max =
  let x = ref (g st 0 0) and y = ref (g st 0 1) and z = ref (g st 0 2) and w = ref (g st 0 3) in
  let pow = ref 2.0 in
  for i = 1 to n_max - 1 do
    let sx = g st i 0 and sy = g st i 1 and sz = g st i 2 and sw = g st i 3 in
    let a, b, c, e =
      match f.func with
      | Sqr | Cube -> Julia_algebra.hmult sx sy sz sw !x !y !z !w
      | Reciprocal ->
          let rx, ry, rz, rw = match Julia_algebra.hreciprocal sx sy sz sw with Some r -> r | None -> (0., 0., 0., 0.) in
          let qx, qy, qz, qw = Julia_algebra.hsqr rx ry rz rw in
          Julia_algebra.hmult !x !y !z !w (-.qx) (-.qy) (-.qz) (-.qw)
      | Func h ->
          let fx, fy, fz, fw = Julia_algebra.hfunc h ~ex:f.ex ~ey:f.ey sx sy sz sw in
          Julia_algebra.hmult fx fy fz fw !x !y !z !w
    in
    x := a;
    y := b;
    z := c;
    w := e;
    pow := !pow *. 2.0
  done;
  let k = match f.func with Sqr -> !pow | Cube | Reciprocal | Func _ -> 1.0 in
  let scaled v = match f.func with Sqr -> v *. k | Cube | Reciprocal | Func _ -> v in
  let n1 = scaled (g st n_max 0) and n2 = scaled (g st n_max 1) and n3 = scaled (g st n_max 2) and n4 = scaled (g st n_max 3) in
  let x = !x and y = !y and z = !z and w = !w in
  Vec.make
    ((x *. n1) +. (y *. n2) +. (z *. n3) +. (w *. n4))
    ((-.y *. n1) +. (x *. n2) -. (w *. n3) +. (z *. n4))
    ((-.z *. n1) -. (w *. n2) +. (x *. n3) +. (y *. n4))

let raw_normal f st n_max = match f.algebra with Quaternion -> quaternion_normal f st n_max | Hypercomplex -> hypercomplex_normal f st n_max

(* ---------------------------------------------------------------------------------------------- *)
(* D_Iteration: the iteration with the distance to step next; the distance, negated when the point
   stays in the set (it is then the precision) *)

let d_iterate f st x y z (dx, dy, dz) =
  start_at f st x y z;
  let i, nrm = run f st in
  if i = 0 then -.f.precision
  else
    match f.algebra with
    | Quaternion ->
        (* the distance estimate: |z_i| log |z_i|² / |z_i'| scaled by 1/2^i (1/3^i) *)
        let x = ref (g st 0 0) and y = ref (g st 0 1) and z = ref (g st 0 2) and w = ref (g st 0 3) in
        let cube = match f.func with Cube -> true | Sqr | Reciprocal | Func _ -> false in
        let pow = ref (if cube then 1.0 /. 3.0 else 1.0 /. 2.0) in
        for j = 1 to i - 1 do
          let sx = g st j 0 and sy = g st j 1 and sz = g st j 2 and sw = g st j 3 in
          let x0 = !x and y0 = !y and z0 = !z and w0 = !w in
          if cube then begin
            x := (x0 *. sx) -. (y0 *. sy) -. (z0 *. sz) -. (w0 *. sw);
            y := (x0 *. sy) +. (y0 *. sx) -. (z0 *. sw) +. (w0 *. sz);
            z := (x0 *. sz) +. (y0 *. sw) +. (z0 *. sx) -. (w0 *. sy);
            w := (x0 *. sw) -. (y0 *. sz) +. (z0 *. sy) +. (w0 *. sx);
            pow := !pow /. 3.0
          end
          else begin
            x := (x0 *. sx) -. (y0 *. sy) -. (z0 *. sz) -. (w0 *. sw);
            y := (x0 *. sy) +. (y0 *. sx) +. (w0 *. sz) -. (z0 *. sw);
            z := (x0 *. sz) +. (z0 *. sx) +. (y0 *. sw) -. (w0 *. sy);
            w := (x0 *. sw) +. (w0 *. sx) +. (z0 *. sy) -. (y0 *. sz);
            pow := !pow /. 2.0
          end
        done;
        let x = !x and y = !y and z = !z and w = !w in
        !pow *. sqrt (nrm /. ((x *. x) +. (y *. y) +. (z *. z) +. (w *. w))) *. log nrm
    | Hypercomplex ->
        (* a step of the value over twice its slope toward the surface, when that is sensible *)
        let h = raw_normal f st (i - 1) in
        let s = (h.x *. dx) +. (h.y *. dy) +. (h.z *. dz) in
        if s < -.hcmplx_tolerance then
          let s = -2.0 *. s in
          if nrm > f.precision *. s && nrm < 30. *. f.precision *. s then nrm /. s else f.precision
        else f.precision

(* ---------------------------------------------------------------------------------------------- *)
(* The ray march (Fractal::All_Intersections) *)

(* Sphere::Intersect about the origin: the entry and exit depths, or None *)
let bound f ox oy oz dx dy dz =
  let cx = 0. -. ox and cy = 0. -. oy and cz = 0. -. oz in
  let ocs = (cx *. cx) +. (cy *. cy) +. (cz *. cz) in
  let tca = (cx *. dx) +. (cy *. dy) +. (cz *. dz) in
  if ocs >= f.radius_sq && tca < Precision.epsilon then None
  else
    let thc = f.radius_sq -. ocs +. (tca *. tca) in
    if thc > Precision.epsilon then
      let h = sqrt thc in
      Some (tca -. h, tca +. h)
    else None

(* The crossings along the ray from [o] along the unit [d], in order: each is reported in
   [w.crossing] (its world point and normal), then [emit depth] receives its world depth and says
   whether to look for more. *)
let march (w : Scratch.t) f (o : Vec.t) (d : Vec.t) emit =
  let stats = w.stats in
  Stats.test stats Stats.fractal;
  let ray =
    match f.trans with
    | None -> Some (o.x, o.y, o.z, d.x, d.y, d.z, 1.0)
    | Some m ->
        let v = Transform.inv_direction m d in
        let l = (v.x *. v.x) +. (v.y *. v.y) +. (v.z *. v.z) in
        if l = 0.0 then None
        else
          let len, v = if l <> 1.0 then let k = 1.0 /. sqrt l in (k, Vec.make (v.x *. k) (v.y *. k) (v.z *. k)) else (l, v) in
          let p = Transform.inv_point m o in
          Some (p.x, p.y, p.z, v.x, v.y, v.z, len)
  in
  match ray with
  | None -> false
  | Some (ox, oy, oz, dx, dy, dz, len) -> (
      match bound f ox oy oz dx dy dz with
      | None -> false
      | Some (_, dmax) when dmax < tolerance -> false
      | Some (dmin, dmax) ->
          let st = stack w f in
          let dir = (dx, dy, dz) in
          let found = ref false in
          let depth = ref (if dmin < tolerance then tolerance else dmin) in
          let nx = ref ((dx *. !depth) +. ox) and ny = ref ((dy *. !depth) +. oy) and nz = ref ((dz *. !depth) +. oz) in
          let inside_of dd = dd < 0. and dist_of dd = Float.abs dd in
          let dd = d_iterate f st !nx !ny !nz dir in
          let current = ref (inside_of dd) and dist = ref (dist_of dd) in
          let over = ref false in
          if !current then begin
            let t2 = 2.0 *. tolerance in
            nx := !nx +. (t2 *. dx);
            ny := !ny +. (t2 *. dy);
            nz := !nz +. (t2 *. dz);
            depth := !depth +. t2;
            if !depth > dmax then over := true
            else begin
              let dd = d_iterate f st !nx !ny !nz dir in
              current := inside_of dd;
              dist := dist_of dd
            end
          end;
          let last = ref false in
          let dist_next = ref 0. and next = ref false in
          let ix = ref 0. and iy = ref 0. and iz = ref 0. in
          while (not !over) && !depth < dmax do
            (* advance by the estimate until the inside state changes *)
            let crossed = ref false in
            while (not !over) && not !crossed do
              if !dist < f.precision then dist := f.precision;
              depth := !depth +. !dist;
              if !depth > dmax then over := true
              else begin
                ix := !nx;
                iy := !ny;
                iz := !nz;
                nx := !nx +. (!dist *. dx);
                ny := !ny +. (!dist *. dy);
                nz := !nz +. (!dist *. dz);
                let dd = d_iterate f st !nx !ny !nz dir in
                next := inside_of dd;
                dist_next := dist_of dd;
                if !next <> !current then begin
                  depth := !depth -. !dist;
                  crossed := true
                end
                else dist := !dist_next
              end
            done;
            if not !over then begin
              (* bisection *)
              while (not !over) && !dist > tolerance do
                dist := !dist *. 0.5;
                let mx = !ix +. (!dist *. dx) and my = !iy +. (!dist *. dy) and mz = !iz +. (!dist *. dz) in
                last := iterate f st mx my mz;
                if !last = !current then begin
                  ix := mx;
                  iy := my;
                  iz := mz;
                  depth := !depth +. !dist;
                  if !depth > dmax then over := true
                end
              done;
              if not !over then begin
                if not !current then begin
                  ix := !ix +. (!dist *. dx);
                  iy := !iy +. (!dist *. dy);
                  iz := !iz +. (!dist *. dz);
                  depth := !depth +. !dist;
                  ignore (iterate f st !ix !iy !iz)
                end
                else if !last <> !current then ignore (iterate f st !ix !iy !iz);
                let p = Vec.make !ix !iy !iz in
                let p = match f.trans with None -> p | Some m -> Transform.point m p in
                (* after the first crossing POV-Ray's depth lags behind its point (it goes on from
                   the point past the crossing with the depth of the crossing): the depth orders
                   the hits, the point (reported with the crossing) is where they are shaded *)
                let t = !depth *. len in
                found := true;
                (* Normal_Calc on the stack as it is: after a point that escaped, POV-Ray's stack
                   holds what the march's deeper iterations left beyond its escape *)
                let n = raw_normal f st f.iterations in
                let n = Transform.normalize (match f.trans with None -> n | Some m -> Transform.normal m n) in
                Crossing.set w.crossing p n 0. 0.;
                if not (emit t) then over := true
                else begin
                  ix := !nx;
                  iy := !ny;
                  iz := !nz;
                  dist := !dist_next;
                  current := !next
                end
              end
            end
          done;
          if !found then Stats.hit stats Stats.fractal;
          !found)

(* ---------------------------------------------------------------------------------------------- *)

(* the first crossing only, as POV-Ray stops for a fractal outside CSG; infinity below [lo] *)
let depth (w : Scratch.t) f o d lo =
  let first = w.depths in
  first.(0) <- infinity;
  ignore
    (march w f o d (fun t ->
         first.(0) <- t;
         w.reported <- true;
         false));
  if first.(0) >= lo then first.(0) else infinity

let hits (w : Scratch.t) f id o d lo n =
  let count = ref n in
  ignore
    (march w f o d (fun t ->
         if t >= lo then count := Scratch.push_reported w !count t id;
         true));
  !count

let local f (p : Vec.t) = match f.trans with None -> p | Some m -> Transform.inv_point m p

let inside_with st f p =
  let q = local f p in
  iterate f st q.x q.y q.z <> f.inverted

let inside stack f p =
  let need = 4 * (f.iterations + 1) in
  inside_with (if Array.length stack >= need then stack else room spare f) f p

let normal_with st f p =
  let q = local f p in
  ignore (iterate f st q.x q.y q.z);
  let n = raw_normal f st f.iterations in
  let n = match f.trans with None -> n | Some m -> Transform.normal m n in
  Transform.normalize n

let normal f p = normal_with (room spare f) f p

let box f =
  let r = f.radius in
  [| -.r; -.r; -.r; r; r; r |]

let bounds f = match f.trans with None -> box f | Some m -> Transform.bounds m (box f)

let pov_box f =
  let r = f.radius in
  let b = [| Precision.f32 (-.r); Precision.f32 (-.r); Precision.f32 (-.r); Precision.f32 (2.0 *. r); Precision.f32 (2.0 *. r); Precision.f32 (2.0 *. r) |] in
  match f.trans with None -> b | Some m -> Pov_box.mapped m b

let traits = { Traits.default with name = "julia_fractal"; inverse_flag = false; inside_holds_inverse = true }
