(* POV-Ray's Solve_Polynomial above degree 4 (math/polysolv.cpp): every such polynomial goes to
   polysolve, Sturm sequences with modified regula falsi and bisection, here with room for
   degree 10 (a cubic sphere sweep's segments). The Sturm routines follow Polysolv's, which
   reproduce POV-Ray's operation order, with polynomials of up to 11 coefficients. *)

let small_enough = 1e-10 (* a coefficient below this is 0 *)
let relerror = 1e-12 (* the relative accuracy asked of a Sturm root *)
let max_iterations = 50
let max_distance = 1e7 (* Sturm roots are looked for in [0, MAX_DISTANCE] *)
let max_order = 10
let stride = max_order + 1

(* A Sturm sequence of at most 11 polynomials: polynomial k has its coefficients in
   seq.(11k …) in ASCENDING powers and its degree in ord.(k). *)
type work = { seq : float array; ord : int array; low : Polysolv.work; mutable eliminated : bool }

let create () = { seq = Array.make (stride * stride) 0.; ord = Array.make stride 0; low = Polysolv.create (); eliminated = false }

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
  Array.blit s bu s br stride;
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

let solve w c n ~eps roots =
  if n > max_order then invalid_arg "Polysolv_high.solve: degree above 10";
  let i = ref 0 in
  while Float.abs c.(!i) < small_enough && !i < n do
    incr i
  done;
  let i = !i in
  let m = n - i in
  w.eliminated <- false;
  if m <= 4 then begin
    (* the closed forms and the small Sturm solver, on the polynomial from its real degree *)
    let k = Polysolv.solve w.low (Array.sub c i (m + 1)) m ~sturm:true ~eps roots in
    w.eliminated <- Polysolv.eliminated w.low;
    k
  end
  else begin
    (* POV-Ray counts the elimination of a root at 0 and solves at full degree all the same:
       the reduced solve's roots are overwritten *)
    if eps > 0. && c.(i + m - 1) <> 0. && Float.abs (c.(i + m) /. c.(i + m - 1)) < eps then w.eliminated <- true;
    sturm w c i m roots 0
  end

let eliminated w = w.eliminated

let eval c i n x =
  let v = ref c.(i) in
  for k = 1 to n do
    v := (!v *. x) +. c.(i + k)
  done;
  !v
