(* POV-Ray's Solve_Polynomial (docs/povray-rules.md §15.6, math/polysolv.cpp of the default build), written
   anew for every degree up to MAX_ORDER (35): closed forms up to 4, Sturm sequences above. The
   arithmetic follows POV-Ray's order of operations term by term: a root that differs in its last
   bit can move a torus's silhouette by a pixel. *)

let small_enough = 1e-10 (* a coefficient below this is 0 *)
let relerror = 1e-12 (* the relative accuracy asked of a Sturm root *)
let max_iterations = 50
let fudge_factor1 = 1e12 (* coefficients this far apart make a quartic "difficult" *)
let max_distance = 1e7 (* Sturm roots are looked for in [0, MAX_DISTANCE] *)
let max_order = 35 (* MAX_ORDER: the highest degree solved *)
let stride = max_order + 1 (* the room of one polynomial of the Sturm sequence *)
let two_pi_3 = 2.0943951023931954923084
let four_pi_3 = 4.1887902047863909846168

(* A Sturm sequence of at most MAX_ORDER + 1 polynomials of degree ≤ MAX_ORDER: polynomial k has
   its coefficients in seq.(stride·k …) in ASCENDING powers (as POV-Ray stores them there) and its
   degree in ord.(k). *)
type work = { seq : float array; ord : int array; cub : float array; croots : float array; mutable eliminated : bool }

let create () =
  { seq = Array.make (stride * stride) 0.; ord = Array.make stride 0; cub = Array.make 4 0.; croots = Array.make 3 0.; eliminated = false }

let eval c i n x =
  let v = ref c.(i) in
  for k = 1 to n do
    v := (!v *. x) +. c.(i + k)
  done;
  !v

(* solve_quadratic: x0·t² + x1·t + x2, with b = −x1 so that the roots are (b ± √d)/2 *)
let quadratic x i y j =
  let a = x.(i) and b = -.x.(i + 1) and c = x.(i + 2) in
  if a = 0. then
    if b = 0. then 0
    else begin
      y.(j) <- c /. b;
      1
    end
  else begin
    let b = b /. a and c = c /. a in
    let d = (b *. b) -. (4. *. 1. *. c) in
    if d > -.small_enough && d < small_enough then begin
      y.(j) <- 0.5 *. b /. 1.;
      1
    end
    else if d < 0. then 0
    else begin
      let d = sqrt d in
      y.(j) <- (b +. d) /. 2.;
      y.(j + 1) <- (b -. d) /. 2.;
      2
    end
  end

(* solve_cubic: three real roots by the trigonometric form, one by Cardano's. A cosine argument
   a hair outside [−1, 1] gives NaN roots, as in C. *)
let cubic x i y j =
  let a0 = x.(i) in
  if a0 = 0. then quadratic x (i + 1) y j
  else begin
    (* divided only when the leading coefficient is not already 1 (written per coefficient: no tuple) *)
    let a1 = if a0 <> 1. then x.(i + 1) /. a0 else x.(i + 1) in
    let a2 = if a0 <> 1. then x.(i + 2) /. a0 else x.(i + 2) in
    let a3 = if a0 <> 1. then x.(i + 3) /. a0 else x.(i + 3) in
    let aa = a1 *. a1 in
    let q = (aa -. (3. *. a2)) /. 9. in
    let r = ((a1 *. (aa -. (4.5 *. a2))) +. (13.5 *. a3)) /. 27. in
    let q3 = q *. q *. q in
    let r2 = r *. r in
    let d = q3 -. r2 in
    let an = a1 /. 3. in
    if d >= 0. then begin
      let d = r /. sqrt q3 in
      let theta = acos d /. 3. in
      let sq = -2. *. sqrt q in
      y.(j) <- (sq *. cos theta) -. an;
      y.(j + 1) <- (sq *. cos (theta +. two_pi_3)) -. an;
      y.(j + 2) <- (sq *. cos (theta +. four_pi_3)) -. an;
      3
    end
    else begin
      let sq = Float.pow (sqrt (r2 -. q3) +. Float.abs r) (1. /. 3.) in
      y.(j) <- (if r < 0. then sq +. (q /. sq) -. an else -.(sq +. (q /. sq)) -. an);
      1
    end
  end

(* The two quadratic factors of Ferrari's method: their roots from y.(j), their number returned. A
   factor whose discriminant is exactly 0 gives its double root with −q2 where the others add q2:
   POV-Ray's slip, kept (§15.6). *)
let[@inline] factors y j c1 z d1 d2 =
  let q1 = d1 *. d1 and q2 = -0.25 *. c1 in
  let n = ref 0 in
  let p = q1 -. (4. *. (z -. d2)) in
  if p = 0. then begin
    y.(j) <- (-0.5 *. d1) -. q2;
    n := 1
  end
  else if p > 0. then begin
    let p = sqrt p in
    y.(j) <- (-0.5 *. (d1 +. p)) +. q2;
    y.(j + 1) <- (-0.5 *. (d1 -. p)) +. q2;
    n := 2
  end;
  let p = q1 -. (4. *. (z +. d2)) in
  if p = 0. then begin
    y.(j + !n) <- (0.5 *. d1) -. q2;
    n := !n + 1
  end
  else if p > 0. then begin
    let p = sqrt p in
    y.(j + !n) <- (0.5 *. (d1 +. p)) +. q2;
    y.(j + !n + 1) <- (0.5 *. (d1 -. p)) +. q2;
    n := !n + 2
  end;
  !n

(* solve_quartic (the default build's, after Ferrari): the resolvent cubic's first root z splits
   the depressed quartic into two quadratics ([factors]). *)
let quartic w x i y j =
  let c0 = x.(i) in
  let c1 = if c0 <> 1. then x.(i + 1) /. c0 else x.(i + 1) in
  let c2 = if c0 <> 1. then x.(i + 2) /. c0 else x.(i + 2) in
  let c3 = if c0 <> 1. then x.(i + 3) /. c0 else x.(i + 3) in
  let c4 = if c0 <> 1. then x.(i + 4) /. c0 else x.(i + 4) in
  let c12 = c1 *. c1 in
  let p = (-0.375 *. c12) +. c2 in
  let q = (0.125 *. c12 *. c1) -. (0.5 *. c1 *. c2) +. c3 in
  let r = (-0.01171875 *. c12 *. c12) +. (0.0625 *. c12 *. c2) -. (0.25 *. c1 *. c3) +. c4 in
  let cub = w.cub in
  cub.(0) <- 1.;
  cub.(1) <- -0.5 *. p;
  cub.(2) <- -.r;
  cub.(3) <- (0.5 *. r *. p) -. (0.125 *. q *. q);
  if cubic cub 0 w.croots 0 = 0 then 0
  else begin
    let z = w.croots.(0) in
    let d1 = (2. *. z) -. p in
    let d1 = if d1 < 0. && d1 > -.small_enough then 0. else d1 in
    if d1 < 0. then 0
    else if d1 < small_enough then
      let d2 = (z *. z) -. r in
      if d2 < 0. then 0 else factors y j c1 z d1 (sqrt d2)
    else
      let d1 = sqrt d1 in
      factors y j c1 z d1 (0.5 *. q /. d1)
  end

(* difficult_coeffs of POV 1.0: "biggest" keeps the sign of the coefficient it came from *)
let difficult c i =
  let biggest = ref 0. in
  for k = 0 to 4 do
    if Float.abs c.(i + k) > !biggest then biggest := c.(i + k)
  done;
  !biggest <> 0.
  &&
  let found = ref false in
  for k = 0 to 4 do
    let x = c.(i + k) in
    if x <> 0. && Float.abs (!biggest /. x) > fudge_factor1 then found := true
  done;
  !found

(* ---------------------------------------------------------------------------------------------- *)
(* Sturm sequences (polysolve, buildsturm, modp, numchanges, sbisect, regula_falsa) *)

(* polynomial k of the sequence at x, ascending coefficients, by Horner's rule from the top *)
let seq_eval w k x =
  let s = w.seq and b = stride * k in
  let n = w.ord.(k) in
  let v = ref s.(b + n) in
  for m = n - 1 downto 0 do
    v := (!v *. x) +. s.(b + m)
  done;
  !v

(* modp: polynomial r := u mod v (v's leading coefficient is ±1), near-zero top coefficients
   cleared; returns r's degree (0 when the remainder is a constant). *)
let modp w u v r =
  let s = w.seq and bu = stride * u and bv = stride * v and br = stride * r in
  let uo = w.ord.(u) and vo = w.ord.(v) in
  (* r := u; the coefficients above u's degree are never read *)
  Array.blit s bu s br (uo + 1);
  if s.(bv + vo) < 0. then begin
    let k = ref (uo - vo - 1) in
    while !k >= 0 do
      s.(br + !k) <- -.s.(br + !k);
      k := !k - 2
    done;
    for k = uo - vo downto 0 do
      for j = vo + k - 1 downto k do
        s.(br + j) <- -.s.(br + j) -. (s.(br + vo + k) *. s.(bv + j - k))
      done
    done
  end
  else
    for k = uo - vo downto 0 do
      for j = vo + k - 1 downto k do
        s.(br + j) <- s.(br + j) -. (s.(br + vo + k) *. s.(bv + j - k))
      done
    done;
  let k = ref (vo - 1) in
  while !k >= 0 && Float.abs s.(br + !k) < small_enough do
    s.(br + !k) <- 0.;
    decr k
  done;
  let o = if !k < 0 then 0 else !k in
  w.ord.(r) <- o;
  o

(* buildsturm: the sequence of polynomial 0 (already in place); returns the index of its last
   member *)
let buildsturm w ord =
  let s = w.seq in
  w.ord.(0) <- ord;
  w.ord.(1) <- ord - 1;
  let f = Float.abs (s.(ord) *. float_of_int ord) in
  for i = 1 to ord do
    s.(stride + i - 1) <- s.(i) *. float_of_int i /. f
  done;
  let sp = ref 2 in
  while modp w (!sp - 2) (!sp - 1) !sp <> 0 do
    let b = stride * !sp and o = w.ord.(!sp) in
    let f = -.Float.abs s.(b + o) in
    for m = o downto 0 do
      s.(b + m) <- s.(b + m) /. f
    done;
    incr sp
  done;
  s.(stride * !sp) <- -.s.(stride * !sp);
  !sp

(* Sign changes along the sequence's values, a 0 counting as a change from it (numchanges, and
   visible_roots at 0 and +∞); written as loops without closures: nothing is allocated. *)
let numchanges w np a =
  let n = ref 0 in
  let lf = ref (seq_eval w 0 a) in
  for k = 1 to np do
    let f = seq_eval w k a in
    if !lf = 0. || !lf *. f < 0. then incr n;
    lf := f
  done;
  !n

(* the changes among the coefficients at [at k] of each member: its constant term (at 0) or its
   leading one (at +∞) *)
let coefficient_changes w np ~leading =
  let s = w.seq in
  let coef k = if leading then s.((stride * k) + w.ord.(k)) else s.(stride * k) in
  let n = ref 0 in
  let lf = ref (coef 0) in
  for k = 1 to np do
    let f = coef k in
    if !lf = 0. || !lf *. f < 0. then incr n;
    lf := f
  done;
  !n

(* visible_roots: sign changes at 0 minus those at +∞ *)
let visible_roots w np = coefficient_changes w np ~leading:false - coefficient_changes w np ~leading:true

(* regula_falsa on polynomial 0 of the sequence, in [a, b]: Some root, or None when the ends have
   the same sign or 50 steps were not enough *)
let regula_falsa w a b y j =
  let fa = seq_eval w 0 a and fb = seq_eval w 0 b in
  if fa *. fb > 0. then false
  else if Float.abs fa < small_enough then (y.(j) <- a; true)
  else if Float.abs fb < small_enough then (y.(j) <- b; true)
  else begin
    let a = ref a and b = ref b and fa = ref fa and fb = ref fb in
    let lfx = ref !fa in
    let result = ref false and its = ref 0 in
    while (not !result) && !its < max_iterations do
      let x = ((!fb *. !a) -. (!fa *. !b)) /. (!fb -. !fa) in
      let fx = seq_eval w 0 x in
      if (Float.abs x > relerror && Float.abs (fx /. x) < relerror) || (Float.abs x <= relerror && Float.abs fx < relerror) then begin
        y.(j) <- x;
        result := true
      end
      else begin
        (* the end with the sign of fx moves to x; the other end's value is halved when fx has
           the sign of the previous step's value *)
        let take_a = if !fa < 0. then fx < 0. else not (fx < 0.) in
        if take_a then begin
          a := x;
          fa := fx;
          if !lfx *. fx > 0. then fb := !fb /. 2.
        end
        else begin
          b := x;
          fb := fx;
          if !lfx *. fx > 0. then fa := !fa /. 2.
        end;
        if Float.abs (!b -. !a) < relerror then begin
          y.(j) <- x;
          result := true
        end
        else begin
          lfx := fx;
          incr its
        end
      end
    done;
    !result
  end

(* sbisect: the roots in [lo, hi], where the sequence has [atmin] and [atmax] sign changes,
   written from y.(j); returns their number *)
let rec sbisect w np lo hi atmin atmax y j =
  (* whether [mid] is close enough to its interval's width to be the root *)
  let narrow lo hi mid = if Float.abs mid > relerror then Float.abs ((hi -. lo) /. mid) < relerror else Float.abs (hi -. lo) < relerror in
  if atmin - atmax = 1 then begin
    if regula_falsa w lo hi y j then 1
    else begin
      (* bisection *)
      let lo = ref lo and hi = ref hi and mid = ref 0. and its = ref 0 and res = ref (-1) in
      while !res < 0 && !its < max_iterations do
        mid := (!lo +. !hi) /. 2.;
        let atmid = numchanges w np !mid in
        if atmid < atmax || atmid > atmin then res := 0
        else if narrow !lo !hi !mid then (y.(j) <- !mid; res := 1)
        else begin
          if atmin - atmid = 0 then lo := !mid else hi := !mid;
          incr its
        end
      done;
      if !res < 0 then (y.(j) <- !mid; 1) else !res
    end
  end
  else begin
    let lo = ref lo and hi = ref hi and mid = ref 0. and its = ref 0 and res = ref (-1) in
    while !res < 0 && !its < max_iterations do
      mid := (!lo +. !hi) /. 2.;
      let atmid = numchanges w np !mid in
      if atmid < atmax || atmid > atmin then res := 0
      else if narrow !lo !hi !mid then (y.(j) <- !mid; res := 1)
      else begin
        let n1 = atmin - atmid and n2 = atmid - atmax in
        if n1 <> 0 && n2 <> 0 then begin
          let n1 = sbisect w np !lo !mid atmin atmid y j in
          let n2 = sbisect w np !mid !hi atmid atmax y (j + n1) in
          res := n1 + n2
        end
        else begin
          if n1 = 0 then lo := !mid else hi := !mid;
          incr its
        end
      end
    done;
    if !res < 0 then (y.(j) <- !mid; 1) else !res
  end

let sturm w c i n y j =
  let s = w.seq in
  for k = 0 to n do
    s.(n - k) <- c.(i + k) /. c.(i)
  done;
  let np = buildsturm w n in
  if visible_roots w np = 0 then 0
  else
    let atmin = numchanges w np 0. and atmax = numchanges w np max_distance in
    if atmin - atmax = 0 then 0 else sbisect w np 0. max_distance atmin atmax y j

let solve_at w c o n ~sturm:use_sturm ~eps roots j =
  if n > max_order then invalid_arg "Polysolv.solve: degree above 35";
  (* the real degree: small leading coefficients dropped *)
  let i = ref o in
  while Float.abs c.(!i) < small_enough && !i - o < n do
    incr i
  done;
  let i = !i in
  w.eliminated <- false;
  match n - (i - o) with
  | 0 -> 0
  | 1 ->
      if c.(i) <> 0. then begin
        roots.(j) <- -.c.(i + 1) /. c.(i);
        1
      end
      else 0
  | 2 -> quadratic c i roots j
  | 3 ->
      (* root elimination: a constant term tiny against the linear one means a root at 0 *)
      if eps > 0. && c.(i + 2) <> 0. && Float.abs (c.(i + 3) /. c.(i + 2)) < eps then (w.eliminated <- true; quadratic c i roots j)
      else if use_sturm then sturm w c i 3 roots j
      else cubic c i roots j
  | 4 ->
      if eps > 0. && c.(i + 3) <> 0. && Float.abs (c.(i + 4) /. c.(i + 3)) < eps then begin
        w.eliminated <- true;
        if use_sturm then sturm w c i 3 roots j else cubic c i roots j
      end
      else if use_sturm || difficult c i then sturm w c i 4 roots j
      else quartic w c i roots j
  | m ->
      (* above 4, always Sturm; a root at 0 is counted as eliminated but POV-Ray then solves the
         whole polynomial anyway, its lower-degree roots overwritten (kept: it is what it draws) *)
      if eps > 0. && c.(i + m - 1) <> 0. && Float.abs (c.(i + m) /. c.(i + m - 1)) < eps then begin
        w.eliminated <- true;
        ignore (sturm w c i (m - 1) roots j)
      end;
      sturm w c i m roots j

let solve w c n ~sturm ~eps roots = solve_at w c 0 n ~sturm ~eps roots 0

let eliminated w = w.eliminated
