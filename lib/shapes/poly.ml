(* The polynomial surfaces poly, cubic and quartic (POV-Ray's shape/poly.cpp): the sum of the
   coefficients times x^i y^j z^k is 0, solid where it is below INSIDE_TOLERANCE. The shape keeps
   its coefficients as written; every modifier composes into its transform, and the ray is brought
   into the poly's space, its direction made unit. *)

type t = { order : int; coeffs : float array; sturm : bool; tr : Transform.t }

let max_order = 35 (* MAX_ORDER *)
let depth_tolerance = 1e-4 (* DEPTH_TOLERANCE: roots at or below it, in poly space, are no hit *)
let inside_tolerance = 1e-4 (* INSIDE_TOLERANCE *)
let root_tolerance = 1e-4 (* ROOT_TOLERANCE: the solver drops a root at 0 below this ratio *)
let coeff_limit = 1e-20 (* COEFF_LIMIT: the quadratic's leading coefficients below it are 0 *)

let term_count n = (n + 1) * (n + 2) * (n + 3) / 6

(* Pascal's triangle as floats (exact), rows 0 … MAX_ORDER: binom.(n·36 + k) = C(n, k) *)
let width = max_order + 1

let binom =
  let b = Array.make (width * width) 0. in
  for n = 0 to max_order do
    b.(n * width) <- 1.;
    for k = 1 to n do
      b.((n * width) + k) <- b.(((n - 1) * width) + k - 1) +. b.(((n - 1) * width) + k)
    done
  done;
  b

let c_nk n k = int_of_float binom.((n * width) + k)

let index order x y z =
  let a = order - x and b = order - x - y and c = order - x - y - z in
  if x < 0 || y < 0 || z < 0 || x + y + z > order || a < 0 || b < 0 || c < 0 then None
  else
    (* Set_Coeff: the tetrahedral count of the terms before x's power, the triangular count
       before y's, then z's place *)
    Some (c_nk a 3 + c_nk a 2 + c_nk a 2 + c_nk a 1 + c_nk b 1 + c_nk b 2 + c_nk c 1)

let make ~order coeffs = { order; coeffs; sturm = false; tr = Transform.identity }

(* The room in [Scratch.poly_room]: the powers of the origin's and the direction's coordinates,
   the binomial expansion of one power, the polynomial in t, its roots and the world depths kept. *)
let at_v = 0
let at_vt = 3 * width
let at_t = 6 * width
let at_eqn = 9 * width
let at_roots = 10 * width
let at_depths = 11 * width

(* intersect_quadratic: the quadric's coefficients along the ray, written out *)
let quadratic a x y z xx yy zz r =
  let x2 = x *. x and y2 = y *. y and z2 = z *. z in
  let xx2 = xx *. xx and yy2 = yy *. yy and zz2 = zz *. zz in
  let ac = (a.(0) *. xx2) +. (a.(1) *. xx *. yy) +. (a.(2) *. xx *. zz) +. (a.(4) *. yy2) +. (a.(5) *. yy *. zz) +. (a.(7) *. zz2) in
  let bc =
    (2. *. a.(0) *. x *. xx)
    +. (a.(1) *. ((x *. yy) +. (xx *. y)))
    +. (a.(2) *. ((x *. zz) +. (xx *. z)))
    +. (a.(3) *. xx)
    +. (2. *. a.(4) *. y *. yy)
    +. (a.(5) *. ((y *. zz) +. (yy *. z)))
    +. (a.(6) *. yy)
    +. (2. *. a.(7) *. z *. zz)
    +. (a.(8) *. zz)
  in
  let cc =
    (a.(0) *. x2) +. (a.(1) *. x *. y) +. (a.(2) *. x *. z) +. (a.(3) *. x) +. (a.(4) *. y2) +. (a.(5) *. y *. z) +. (a.(6) *. y)
    +. (a.(7) *. z2) +. (a.(8) *. z) +. a.(9)
  in
  if Float.abs ac < coeff_limit then
    if Float.abs bc < coeff_limit then 0
    else begin
      r.(at_roots) <- -.cc /. bc;
      1
    end
  else
    let d = (bc *. bc) -. (4.0 *. ac *. cc) in
    if d < 0. then 0
    else
      let d = sqrt d in
      let bc = -.bc in
      let t = 2.0 *. ac in
      r.(at_roots) <- (bc +. d) /. t;
      r.(at_roots + 1) <- (bc -. d) /. t;
      2

(* intersect: each term c·x^i y^j z^k with the ray's coordinates put in, each power expanded by
   the binomial theorem and the three products summed into the polynomial in t (eqn.(0) the
   coefficient of t^order); then Solve_Polynomial on it from its first non-zero coefficient, when
   its degree is above 1. Counts "Roots tested" and "eliminated". *)
let general (w : Scratch.t) ~count p px py pz dx dy dz =
  let r = w.poly_room and order = p.order and a = p.coeffs in
  for j = 0 to 2 do
    r.(at_v + (j * width)) <- 1.;
    r.(at_vt + (j * width)) <- 1.
  done;
  r.(at_v + 1) <- px;
  r.(at_v + width + 1) <- py;
  r.(at_v + (2 * width) + 1) <- pz;
  r.(at_vt + 1) <- dx;
  r.(at_vt + width + 1) <- dy;
  r.(at_vt + (2 * width) + 1) <- dz;
  for i = 2 to order do
    for j = 0 to 2 do
      let v = at_v + (j * width) and vt = at_vt + (j * width) in
      r.(v + i) <- r.(v + 1) *. r.(v + i - 1);
      r.(vt + i) <- r.(vt + 1) *. r.(vt + i - 1)
    done
  done;
  for i = 0 to order do
    r.(at_eqn + i) <- 0.
  done;
  (* t.(axis, h): C(n, h)·d^(n−h)·p^h for the axis's current power n *)
  let expand axis n =
    let v = at_v + (axis * width) and vt = at_vt + (axis * width) and t = at_t + (axis * width) in
    for h = 0 to n do
      r.(t + h) <- binom.((n * width) + h) *. r.(vt + n - h) *. r.(v + h)
    done
  in
  let term = ref 0 in
  for i = order downto 0 do
    expand 0 i;
    for j = order - i downto 0 do
      expand 1 j;
      for k = order - (i + j) downto 0 do
        let c = a.(!term) in
        if c <> 0. then begin
          expand 2 k;
          let offset = order - (i + j + k) in
          (* one product c·t0·t1·t2 added into the coefficient of its power of t *)
          let add i1 j1 k1 =
            let h = at_eqn + offset + i1 + j1 + k1 in
            let v = c *. r.(at_t + i1) in
            let v = v *. r.(at_t + width + j1) in
            let v = v *. r.(at_t + (2 * width) + k1) in
            r.(h) <- r.(h) +. v
          in
          (* The order of the sums is that of POV-Ray's binary, not of its source: built with
             -O3, GCC vectorizes the j1 loop as an outer loop over pairs (j1, j1 + 1), so for
             each k1 the pair's two products are added one after the other, and an odd last j1
             is done alone after the pairs. The sums then round differently (an ulp of a
             coefficient, enough to move a grazing root: checked against POV-Ray's trace()). *)
          for i1 = 0 to i do
            let pairs = (j + 1) / 2 in
            for p = 0 to pairs - 1 do
              for k1 = 0 to k do
                add i1 (2 * p) k1;
                add i1 ((2 * p) + 1) k1
              done
            done;
            if (j + 1) mod 2 = 1 then
              for k1 = 0 to k do
                add i1 j k1
              done
          done
        end;
        incr term
      done
    done
  done;
  let i = ref 0 in
  while !i <= order && r.(at_eqn + !i) = 0. do
    incr i
  done;
  let deg = order - !i in
  if deg > 1 then begin
    let n = Polysolv.solve_at w.quartic r (at_eqn + !i) deg ~sturm:p.sturm ~eps:root_tolerance r at_roots in
    if count then begin
      Stats.test w.stats Stats.roots;
      if Polysolv.eliminated w.quartic then Stats.hit w.stats Stats.roots
    end;
    n
  end
  else 0

(* All_Intersections: the ray brought into poly space (MInvTransPoint, MInvTransDirection, the
   direction scaled by the reciprocal of its length), the roots found, and those beyond
   DEPTH_TOLERANCE (in poly space; none in the robust mode) that repeat no earlier root kept as
   world depths with their world points, from [at_depths] in fours (depth, x, y, z). Counted as
   POV-Ray counts it ("Quartic/Poly"). *)
let solve (w : Scratch.t) ~count p (o : Vec.t) (d : Vec.t) =
  let m = p.tr and r = w.poly_room in
  let px = (o.x *. m.i00) +. (o.y *. m.i10) +. (o.z *. m.i20) +. m.i30 in
  let py = (o.x *. m.i01) +. (o.y *. m.i11) +. (o.z *. m.i21) +. m.i31 in
  let pz = (o.x *. m.i02) +. (o.y *. m.i12) +. (o.z *. m.i22) +. m.i32 in
  let dx = (d.x *. m.i00) +. (d.y *. m.i10) +. (d.z *. m.i20) in
  let dy = (d.x *. m.i01) +. (d.y *. m.i11) +. (d.z *. m.i21) in
  let dz = (d.x *. m.i02) +. (d.y *. m.i12) +. (d.z *. m.i22) in
  let len = sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
  let k = 1.0 /. len in
  let dx = dx *. k and dy = dy *. k and dz = dz *. k in
  let stats = w.stats in
  if count then Stats.test stats Stats.poly;
  let cnt = if p.order = 2 then quadratic p.coeffs px py pz dx dy dz r else general w ~count p px py pz dx dy dz in
  if count && cnt > 0 then Stats.hit stats Stats.poly;
  let near = if w.robust then 0. else depth_tolerance in
  let kept = ref 0 in
  for i = 0 to cnt - 1 do
    let t = r.(at_roots + i) in
    if t > near then begin
      let same = ref false in
      for j = 0 to i - 1 do
        if r.(at_roots + j) = t then same := true
      done;
      if not !same then begin
        (* VEvaluateRay in poly space, then MTransPoint back to the world *)
        let x = px +. (t *. dx) and y = py +. (t *. dy) and z = pz +. (t *. dz) in
        let b = at_depths + (4 * !kept) in
        r.(b) <- t /. len;
        r.(b + 1) <- (x *. m.m00) +. (y *. m.m10) +. (z *. m.m20) +. m.m30;
        r.(b + 2) <- (x *. m.m01) +. (y *. m.m11) +. (z *. m.m21) +. m.m31;
        r.(b + 3) <- (x *. m.m02) +. (y *. m.m12) +. (z *. m.m22) +. m.m32;
        incr kept
      end
    end
  done;
  !kept

let crossings w p o d = solve w ~count:true p o d
let crossing (w : Scratch.t) i = w.poly_room.(at_depths + (4 * i))

(* The hit point POV-Ray shades: the crossings found again (uncounted), the one at [depth] *)
let hit_point (w : Scratch.t) p o d depth =
  let n = solve w ~count:false p o d in
  let r = w.poly_room in
  let pt = ref (Vec.madd o depth d) in
  for i = n - 1 downto 0 do
    let b = at_depths + (4 * i) in
    if r.(b) = depth then pt := Vec.make r.(b + 1) r.(b + 2) r.(b + 3)
  done;
  !pt

let depth (w : Scratch.t) p o d lo =
  let n = crossings w p o d in
  let r = w.poly_room in
  (* of equal depths the last pushed wins, as POV-Ray pops its stack; they are all distinct here *)
  let best = ref infinity in
  for i = n - 1 downto 0 do
    let t = r.(at_depths + (4 * i)) in
    if t < !best && t >= lo then best := t
  done;
  !best

let hits (w : Scratch.t) p id o d lo n =
  let k = crossings w p o d in
  let r = w.poly_room in
  let n = ref n in
  for i = 0 to k - 1 do
    let b = at_depths + (4 * i) in
    if r.(b) >= lo then n := Scratch.push_hit w !n r.(b) (-1) id r.(b + 1) r.(b + 2) r.(b + 3)
  done;
  !n

(* inside: the polynomial's value, the powers x^i = x·x^(i−1), each non-zero term's product
   taken from the left *)
let value p (q : Vec.t) =
  let order = p.order and a = p.coeffs in
  let xs = Array.make (order + 1) 1. and ys = Array.make (order + 1) 1. and zs = Array.make (order + 1) 1. in
  if order >= 1 then begin
    xs.(1) <- q.x;
    ys.(1) <- q.y;
    zs.(1) <- q.z
  end;
  for i = 2 to order do
    xs.(i) <- xs.(1) *. xs.(i - 1);
    ys.(i) <- ys.(1) *. ys.(i - 1);
    zs.(i) <- zs.(1) *. zs.(i - 1)
  done;
  let result = ref 0. and term = ref 0 in
  for i = order downto 0 do
    for j = order - i downto 0 do
      for k = order - (i + j) downto 0 do
        let c = a.(!term) in
        if c <> 0. then result := !result +. (c *. xs.(i) *. ys.(j) *. zs.(k));
        incr term
      done
    done
  done;
  !result

let inside p pt = value p (Transform.inv_point p.tr pt) < inside_tolerance

(* normal0 (orders above 4): every term's three partial derivatives, zero coefficients included *)
let gradient_any p (q : Vec.t) =
  let order = p.order and a = p.coeffs in
  let xs = Array.make (order + 1) 1. and ys = Array.make (order + 1) 1. and zs = Array.make (order + 1) 1. in
  xs.(1) <- q.x;
  ys.(1) <- q.y;
  zs.(1) <- q.z;
  for i = 2 to order do
    xs.(i) <- q.x *. xs.(i - 1);
    ys.(i) <- q.y *. ys.(i - 1);
    zs.(i) <- q.z *. zs.(i - 1)
  done;
  let gx = ref 0. and gy = ref 0. and gz = ref 0. and term = ref 0 in
  for i = order downto 0 do
    for j = order - i downto 0 do
      for k = order - (i + j) downto 0 do
        let c = a.(!term) in
        if i >= 1 then gx := !gx +. (float_of_int i *. c *. (xs.(i - 1) *. ys.(j) *. zs.(k)));
        if j >= 1 then gy := !gy +. (float_of_int j *. c *. (xs.(i) *. ys.(j - 1) *. zs.(k)));
        if k >= 1 then gz := !gz +. (float_of_int k *. c *. (xs.(i) *. ys.(j) *. zs.(k - 1)));
        incr term
      done
    done
  done;
  Vec.make !gx !gy !gz

(* normal1 (orders 2 to 4): the partial derivatives written out, in POV-Ray's grouping *)
let gradient_low p (q : Vec.t) =
  let a = p.coeffs and x = q.x and y = q.y and z = q.z in
  match p.order with
  | 2 ->
      Vec.make
        ((2. *. a.(0) *. x) +. (a.(1) *. y) +. (a.(2) *. z) +. a.(3))
        ((a.(1) *. x) +. (2. *. a.(4) *. y) +. (a.(5) *. z) +. a.(6))
        ((a.(2) *. x) +. (a.(5) *. y) +. (2. *. a.(7) *. z) +. a.(8))
  | 3 ->
      let x2 = x *. x and y2 = y *. y and z2 = z *. z in
      Vec.make
        ((3. *. a.(0) *. x2)
        +. (2. *. x *. ((a.(1) *. y) +. (a.(2) *. z) +. a.(3)))
        +. (a.(4) *. y2)
        +. (y *. ((a.(5) *. z) +. a.(6)))
        +. (a.(7) *. z2) +. (a.(8) *. z) +. a.(9))
        ((a.(1) *. x2)
        +. (x *. ((2. *. a.(4) *. y) +. (a.(5) *. z) +. a.(6)))
        +. (3. *. a.(10) *. y2)
        +. (2. *. y *. ((a.(11) *. z) +. a.(12)))
        +. (a.(13) *. z2) +. (a.(14) *. z) +. a.(15))
        ((a.(2) *. x2)
        +. (x *. ((a.(5) *. y) +. (2. *. a.(7) *. z) +. a.(8)))
        +. (a.(11) *. y2)
        +. (y *. ((2. *. a.(13) *. z) +. a.(14)))
        +. (3. *. a.(16) *. z2) +. (2. *. a.(17) *. z) +. a.(18))
  | 4 ->
      let x2 = x *. x and y2 = y *. y and z2 = z *. z in
      let x3 = x *. x2 and y3 = y *. y2 and z3 = z *. z2 in
      Vec.make
        ((4. *. a.(0) *. x3)
        +. (3. *. x2 *. ((a.(1) *. y) +. (a.(2) *. z) +. a.(3)))
        +. (2. *. x *. ((a.(4) *. y2) +. (y *. ((a.(5) *. z) +. a.(6))) +. (a.(7) *. z2) +. (a.(8) *. z) +. a.(9)))
        +. (a.(10) *. y3)
        +. (y2 *. ((a.(11) *. z) +. a.(12)))
        +. (y *. ((a.(13) *. z2) +. (a.(14) *. z) +. a.(15)))
        +. (a.(16) *. z3) +. (a.(17) *. z2) +. (a.(18) *. z) +. a.(19))
        ((a.(1) *. x3)
        +. (x2 *. ((2. *. a.(4) *. y) +. (a.(5) *. z) +. a.(6)))
        +. (x *. ((3. *. a.(10) *. y2) +. (2. *. y *. ((a.(11) *. z) +. a.(12))) +. (a.(13) *. z2) +. (a.(14) *. z) +. a.(15)))
        +. (4. *. a.(20) *. y3)
        +. (3. *. y2 *. ((a.(21) *. z) +. a.(22)))
        +. (2. *. y *. ((a.(23) *. z2) +. (a.(24) *. z) +. a.(25)))
        +. (a.(26) *. z3) +. (a.(27) *. z2) +. (a.(28) *. z) +. a.(29))
        ((a.(2) *. x3)
        +. (x2 *. ((a.(5) *. y) +. (2. *. a.(7) *. z) +. a.(8)))
        +. (x *. ((a.(11) *. y2) +. (y *. ((2. *. a.(13) *. z) +. a.(14))) +. (3. *. a.(16) *. z2) +. (2. *. a.(17) *. z) +. a.(18)))
        +. (a.(21) *. y3)
        +. (y2 *. ((2. *. a.(23) *. z) +. a.(24)))
        +. (y *. ((3. *. a.(26) *. z2) +. (2. *. a.(27) *. z) +. a.(28)))
        +. (4. *. a.(30) *. z3) +. (3. *. a.(31) *. z2) +. (2. *. a.(32) *. z) +. a.(33))
  | _ -> Vec.make a.(0) a.(1) a.(2)

let gradient p q = if p.order > 4 then gradient_any p q else gradient_low p q

(* Poly::Normal: the gradient in poly space, by the inverse transpose, times the reciprocal of its
   length; <1, 0, 0> where it vanishes *)
let normal p pt =
  let g = Transform.normal p.tr (gradient p (Transform.inv_point p.tr pt)) in
  let v = Vec.dot g g in
  if v > 0. then
    let k = 1.0 /. sqrt v in
    Vec.make (g.x *. k) (g.y *. k) (g.z *. k)
  else Vec.make 1. 0. 0.

let traits = { Traits.default with name = "poly"; box_test_free = true; sturm = Sturm_bool }
