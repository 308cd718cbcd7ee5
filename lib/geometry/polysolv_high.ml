(* POV-Ray's Solve_Polynomial for degrees 5 and 6 (math/polysolv.cpp, its default branch): only
   Sturm sequences solve them. Degrees up to 4 go to [Polysolv] unchanged, so the torus and every
   other user of it keep their bit-exact roots. The Sturm machinery is Polysolv's, written again
   here with room for a degree-6 sequence (7 polynomials of 7 coefficients); its arithmetic is
   POV-Ray's, operation for operation. *)

let small_enough = 1e-10
let relerror = 1e-12
let max_iterations = 50
let max_distance = 1e7
let max_degree = 6
let stride = max_degree + 1

type work = { low : Polysolv.work; seq : float array; ord : int array; part : float array; mutable eliminated : bool }

let create () =
  { low = Polysolv.create (); seq = Array.make (stride * stride) 0.; ord = Array.make stride 0; part = Array.make 5 0.; eliminated = false }

let seq_eval w k x =
  let s = w.seq and b = stride * k in
  let n = w.ord.(k) in
  let v = ref s.(b + n) in
  for m = n - 1 downto 0 do
    v := (!v *. x) +. s.(b + m)
  done;
  !v

(* modp: r := u mod v (v's leading coefficient ±1), near-zero top coefficients cleared *)
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

let numchanges w np a =
  let n = ref 0 in
  let lf = ref (seq_eval w 0 a) in
  for k = 1 to np do
    let f = seq_eval w k a in
    if !lf = 0. || !lf *. f < 0. then incr n;
    lf := f
  done;
  !n

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

let visible_roots w np = coefficient_changes w np ~leading:false - coefficient_changes w np ~leading:true

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

let rec sbisect w np lo hi atmin atmax y j =
  let narrow lo hi mid = if Float.abs mid > relerror then Float.abs ((hi -. lo) /. mid) < relerror else Float.abs (hi -. lo) < relerror in
  if atmin - atmax = 1 then begin
    if regula_falsa w lo hi y j then 1
    else begin
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

let sturm w c i n y =
  let s = w.seq in
  for k = 0 to n do
    s.(n - k) <- c.(i + k) /. c.(i)
  done;
  let np = buildsturm w n in
  if visible_roots w np = 0 then 0
  else
    let atmin = numchanges w np 0. and atmax = numchanges w np max_distance in
    if atmin - atmax = 0 then 0 else sbisect w np 0. max_distance atmin atmax y 0

let solve w c n ~sturm:use_sturm ~eps roots =
  if n > max_degree then invalid_arg "Polysolv_high.solve: degree above 6";
  let i = ref 0 in
  while Float.abs c.(!i) < small_enough && !i < n do
    incr i
  done;
  let i = !i in
  w.eliminated <- false;
  if n - i <= 4 then begin
    (* the real degree is one Polysolv solves: its coefficients moved to the front *)
    Array.blit c i w.part 0 (n - i + 1);
    let k = Polysolv.solve w.low w.part (n - i) ~sturm:use_sturm ~eps roots in
    w.eliminated <- Polysolv.eliminated w.low;
    k
  end
  else begin
    (* the default branch: a root eliminated at 0 is solved for, then overwritten by the full
       solve, as POV-Ray does (only the statistic remains) *)
    let m = n - i in
    if eps > 0. && c.(i + m - 1) <> 0. && Float.abs (c.(i + m) /. c.(i + m - 1)) < eps then w.eliminated <- true;
    sturm w c i m roots
  end

let eliminated w = w.eliminated
