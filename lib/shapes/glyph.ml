(* A text object's letter (docs/povray-rules.md §15.9): TrueType::GlyphIntersect, Inside_Glyph and
   solve_quad, their arithmetic in the same order, so that a ray grazing an edge goes the same way. *)

type outline = {
  segs : float array;
  nseg : int;
  contours : int;
  xmin : int;
  ymin : int;
  xmax : int;
  ymax : int;
  units_per_em : int;
}

type t = { outline : outline; depth : float; tr : Transform.t }

let epsilon = Precision.epsilon
let tolerance = 1e-6 (* TTF_Tolerance *)
let coeff_limit = 1e-20 (* COEFF_LIMIT *)

(* The walk over a contour: a point on the curve ends a line from the previous end; a control
   point starts a curve that ends at the next point, or halfway to it when that is a control point
   too, or at the first point for the last one. The contour's first point is repeated at its end
   (ConvertOutlineToGlyph), and the walk starts from the first point whatever its flag. *)
let outline_of_contours ~units_per_em ~xmin ~ymin ~xmax ~ymax contours =
  let acc = ref [] in
  List.iter
    (fun (xs, ys, on) ->
      let count = Array.length xs in
      if count > 0 then begin
        let x = Array.append xs [| xs.(0) |] and y = Array.append ys [| ys.(0) |] and f = Array.append on [| on.(0) |] in
        let x0 = ref x.(0) and y0 = ref y.(0) in
        for j = 1 to count do
          let x1 = x.(j) and y1 = y.(j) in
          if f.(j) then begin
            acc := [| 0.; !x0; !y0; x1; y1; 0.; 0. |] :: !acc;
            x0 := x1;
            y0 := y1
          end
          else begin
            let x2, y2 =
              if j = count then (x.(0), y.(0))
              else if not f.(j + 1) then (0.5 *. (x1 +. x.(j + 1)), 0.5 *. (y1 +. y.(j + 1)))
              else (x.(j + 1), y.(j + 1))
            in
            acc := [| 1.; !x0; !y0; x1; y1; x2; y2 |] :: !acc;
            x0 := x2;
            y0 := y2
          end
        done
      end)
    contours;
  let segs = Array.concat (List.rev !acc) in
  { segs; nseg = Array.length segs / 7; contours = List.length contours; xmin; ymin; xmax; ymax; units_per_em }

(* solve_quad: the roots of a·s² − b·s + c = 0 (given as x0 s² + x1 s + x2) within [0, 1], a
   discriminant below EPSILON counting as none, the "+" root first. *)
type roots = { mutable n : int; mutable r0 : float; mutable r1 : float }

let solve_quad q x0 x1 x2 =
  let a = x0 and b = -.x1 and c = x2 in
  q.n <- 0;
  if Float.abs a < coeff_limit then begin
    if Float.abs b >= coeff_limit then begin
      let r = c /. b in
      if r >= 0. && r <= 1. then (q.r0 <- r; q.n <- 1)
    end
  end
  else begin
    let d = (b *. b) -. (4.0 *. a *. c) in
    if d >= epsilon then begin
      let d = sqrt d in
      let t = 2.0 *. a in
      let r = (b +. d) /. t in
      if r >= 0. && r <= 1. then begin
        q.r0 <- r;
        q.n <- 1;
        let r = (b -. d) /. t in
        if r >= 0. && r <= 1. then (q.r1 <- r; q.n <- 2)
      end
      else
        let r = (b -. d) /. t in
        if r >= 0. && r <= 1. then (q.r0 <- r; q.n <- 1)
    end
  end

let inside_with q (o : outline) x y =
  let s = o.segs in
  let crossings = ref 0 in
  for i = 0 to o.nseg - 1 do
    let b = 7 * i in
    let x0 = s.(b + 1) and y0 = s.(b + 2) and x1 = s.(b + 3) and y1 = s.(b + 4) in
    if s.(b) = 0. then begin
      (* a line: the crossing test of a half-line along +x *)
      if y0 <> y1 then begin
        let qi = y0 < y and qj = y1 < y in
        if qi <> qj then begin
          let ri = x0 > x and rj = x1 > x in
          if ri && rj then incr crossings
          else if ri || rj then begin
            let m = (y1 -. y0) /. (x1 -. x0) in
            let bb = (y1 -. y) -. (m *. (x1 -. x)) in
            if bb /. m < epsilon then incr crossings
          end
        end
      end
    end
    else begin
      let x2 = s.(b + 5) and y2 = s.(b + 6) in
      if not ((y0 < y && y1 < y && y2 < y) || (y0 > y && y1 > y && y2 > y)) then begin
        solve_quad q (y0 -. (2.0 *. y1) +. y2) (2.0 *. (y1 -. y0)) (y0 -. y);
        (* a root at an end counts only where y is really within the curve's span there *)
        let drop r =
          if r <= epsilon then (y <= y0 && y < y1) || (y >= y0 && y > y1)
          else if r >= 1.0 -. epsilon then (y < y2 && y < y1) || (y > y2 && y > y1)
          else false
        in
        let ri = ref 0 in
        while !ri < q.n do
          let r = if !ri = 0 then q.r0 else q.r1 in
          if drop r then begin
            q.n <- q.n - 1;
            if q.n > !ri then q.r0 <- q.r1
          end
          else incr ri
        done;
        if q.n > 0 then begin
          let xt0 = x0 -. (2.0 *. x1) +. x2 and xt1 = 2.0 *. (x1 -. x0) and xt2 = x0 in
          let xc = (((xt0 *. q.r0) +. xt1) *. q.r0) +. xt2 in
          if xc > x then incr crossings;
          if q.n > 1 then begin
            let xc = (((xt0 *. q.r1) +. xt1) *. q.r1) +. xt2 in
            if xc > x then incr crossings
          end
        end
      end
    end
  done;
  !crossings land 1 <> 0

let inside_outline o x y = inside_with { n = 0; r0 = 0.; r1 = 0. } o x y

let max_hits (o : outline) = 2 * (2 + (2 * o.nseg))

let part_scale = 2147483648. (* 2^31: a curve's parameter kept in the low 31 bits of its part *)

let[@inline] push out k t part =
  out.(2 * k) <- t;
  out.((2 * k) + 1) <- part;
  k + 1

let crossings g (o : Vec.t) (d : Vec.t) out =
  let p = Transform.inv_point g.tr o and d = Transform.inv_direction g.tr d in
  let ol = g.outline in
  let q = { n = 0; r0 = 0.; r1 = 0. } in
  let k = ref 0 in
  (* GetZeroOneHits: the faces z = 0 and z = depth, where the point is inside the outline *)
  if Float.abs d.z >= epsilon then begin
    let t = -.p.z /. d.z in
    let x0 = p.x +. (t *. d.x) and y0 = p.y +. (t *. d.y) in
    let t0 = if inside_with q ol x0 y0 then t else -1.0 in
    let t = t +. (g.depth /. d.z) in
    let x1 = p.x +. (t *. d.x) and y1 = p.y +. (t *. d.y) in
    let t1 = if inside_with q ol x1 y1 then t else -1.0 in
    if t0 > 0.0 && t0 > tolerance then k := push out !k t0 0.;
    if t1 > 0.0 && t1 > tolerance then k := push out !k t1 1.
  end;
  let parallel = Float.abs d.x < epsilon && Float.abs d.y < epsilon in
  if not parallel then begin
    let dirflag = Float.abs d.x >= epsilon in
    let a = d.y and b = -.d.x and c = (p.y *. d.x) -. (p.x *. d.y) in
    let s = ol.segs in
    for i = 0 to ol.nseg - 1 do
      let base = 7 * i in
      let x0 = s.(base + 1) and y0 = s.(base + 2) and x1 = s.(base + 3) and y1 = s.(base + 4) in
      let part = float_of_int (i + 1) *. part_scale in
      if s.(base) = 0. then begin
        let d0 = x1 -. x0 and d1 = y1 -. y0 in
        let t0 = (d1 *. d.x) -. (d0 *. d.y) in
        if Float.abs t0 >= epsilon then begin
          let t = ((d.x *. (p.y -. y0)) -. (d.y *. (p.x -. x0))) /. t0 in
          if not (t < 0.0 || t > 1.0) then begin
            let t = if dirflag then (x0 +. (t *. d0) -. p.x) /. d.x else (y0 +. (t *. d1) -. p.y) /. d.y in
            let z = p.z +. (t *. d.z) in
            if z >= 0. && z <= g.depth && t > tolerance then k := push out !k t part
          end
        end
      end
      else begin
        let x2 = s.(base + 5) and y2 = s.(base + 6) in
        let xt2 = x0 -. (2.0 *. x1) +. x2 and xt1 = 2.0 *. (x1 -. x0) and xt0 = x0 in
        let yt2 = y0 -. (2.0 *. y1) +. y2 and yt1 = 2.0 *. (y1 -. y0) and yt0 = y0 in
        solve_quad q ((a *. xt2) +. (b *. yt2)) ((a *. xt1) +. (b *. yt1)) ((a *. xt0) +. (b *. yt0) +. c);
        for l = 0 to q.n - 1 do
          let sl = if l = 0 then q.r0 else q.r1 in
          let t =
            if dirflag then ((sl *. sl *. xt2) +. (sl *. xt1) +. xt0 -. p.x) /. d.x
            else ((sl *. sl *. yt2) +. (sl *. yt1) +. yt0 -. p.y) /. d.y
          in
          let z = p.z +. (t *. d.z) in
          if z >= 0. && z <= g.depth && t > tolerance then
            k := push out !k t (part +. Float.round (sl *. (part_scale -. 1.)))
        done
      end
    done
  end;
  !k

let normal g part =
  let n =
    if part = 0 then Vec.make 0. 0. (-1.)
    else if part = 1 then Vec.make 0. 0. 1.
    else
      let i = (part lsr 31) - 1 and sq = float_of_int (part land 0x7fffffff) /. (part_scale -. 1.) in
      let s = g.outline.segs and base = 7 * i in
      let x0 = s.(base + 1) and y0 = s.(base + 2) and x1 = s.(base + 3) and y1 = s.(base + 4) in
      if s.(base) = 0. then Vec.make (y1 -. y0) (-.(x1 -. x0)) 0.
      else
        let x2 = s.(base + 5) and y2 = s.(base + 6) in
        let xt2 = x0 -. (2.0 *. x1) +. x2 and xt1 = 2.0 *. (x1 -. x0) in
        let yt2 = y0 -. (2.0 *. y1) +. y2 and yt1 = 2.0 *. (y1 -. y0) in
        Vec.make ((2.0 *. yt2 *. sq) +. yt1) ((-2.0 *. xt2 *. sq) -. xt1) 0.
  in
  Transform.normalize (Transform.normal g.tr n)

let inside g p =
  let q = Transform.inv_point g.tr p in
  let inn = q.z >= 0.0 && q.z <= g.depth && inside_outline g.outline q.x q.y in
  inn

let box g =
  let o = g.outline in
  let f = 1.0 /. float_of_int o.units_per_em in
  [| float_of_int o.xmin *. f; float_of_int o.ymin *. f; -.tolerance; float_of_int o.xmax *. f; float_of_int o.ymax *. f; g.depth +. tolerance |]

(* The crossings counted as POV-Ray counts them ("True Type Font" tests and successes), left as
   (depth, part) pairs in [w.glyph_crossings]. *)
let counted_crossings (w : Scratch.t) g o d =
  let stats = w.stats in
  Stats.test stats Stats.glyph;
  let room = max_hits g.outline in
  if Array.length w.glyph_crossings.room < room then w.glyph_crossings.room <- Array.make room 0.;
  let k = crossings g o d w.glyph_crossings.room in
  if k > 0 then Stats.hit stats Stats.glyph;
  k

let depth (w : Scratch.t) g o d lo =
  let k = counted_crossings w g o d in
  let h = w.glyph_crossings.room in
  let best = ref infinity and part = ref 0 in
  for i = 0 to k - 1 do
    let t = h.(2 * i) in
    if t >= lo && t < !best then begin
      best := t;
      part := int_of_float h.((2 * i) + 1)
    end
  done;
  if !best < infinity then w.part <- !part;
  !best

let hits (w : Scratch.t) g id o d lo n =
  let k = counted_crossings w g o d in
  let n = ref n in
  for i = 0 to k - 1 do
    let h = w.glyph_crossings.room in
    n := Scratch.push_ray w !n lo h.(2 * i) (int_of_float h.((2 * i) + 1)) id o d
  done;
  !n

let bounds g = Transform.bounds g.tr (box g)
let pov_box g = let b = box g in Pov_box.mapped g.tr (Pov_box.of_min_max (Array.sub b 0 3) (Array.sub b 3 3))

let traits = { Traits.default with name = "glyph" }
