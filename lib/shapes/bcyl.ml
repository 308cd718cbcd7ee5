(* POV-Ray's bounding cylinders of a lathe or surface of revolution (bounding/bcyl.cpp): each
   segment lies in a thick cylinder, between two radii and two heights; the distinct radii
   (squared) and heights are intersected once per ray, and each segment's entry distance comes
   from them. *)

type entry = { r1 : int; r2 : int; h1 : int; h2 : int }
type t = { radius : float array; height : float array; entry : entry array }

let epsilon = Precision.epsilon

(* Create_BCyl: every distinct value once, in the order met (r1, r2, h1, h2 of each segment) *)
let make (r1 : float array) (r2 : float array) (h1 : float array) (h2 : float array) =
  let radii = ref [||] and heights = ref [||] in
  let index tbl v =
    let n = Array.length !tbl in
    let rec find j = if j = n then (tbl := Array.append !tbl [| v |]; n) else if v = !tbl.(j) then j else find (j + 1) in
    find 0
  in
  let entry =
    Array.init (Array.length r1) (fun i ->
        let a = index radii r1.(i) in
        let b = index radii r2.(i) in
        let c = index heights h1.(i) in
        let d = index heights h2.(i) in
        { r1 = a; r2 = b; h1 = c; h2 = d })
  in
  { radius = Array.map (fun r -> r *. r) !radii; height = !heights; entry }

(* the room's layout: the intervals (entry distance, segment) first, then per radius (n, d0, w0,
   d1, w1), per height (n, d0, w0), and 8 distances of one thick cylinder *)
let room_size b = (2 * Array.length b.entry) + (5 * Array.length b.radius) + (3 * Array.length b.height) + 8

let intersect (w : Scratch.t) b px py pz dx dy dz =
  if Array.length w.bcyl.room < room_size b then w.bcyl.room <- Array.make (2 * room_size b) 0.;
  let room = w.bcyl.room in
  let nr = Array.length b.radius and nh = Array.length b.height and number = Array.length b.entry in
  let rbase = 2 * number in
  let hbase = rbase + (5 * nr) in
  let dbase = hbase + (3 * nh) in
  (* intersect_bound_elements *)
  let a = (dx *. dx) +. (dz *. dz) and bb0 = (px *. dx) +. (pz *. dz) in
  let bb = bb0 *. bb0 and b2 = 2. *. bb0 and c = (px *. px) +. (pz *. pz) in
  if dy < -.epsilon || dy > epsilon then
    for i = 0 to nh - 1 do
      let k = (b.height.(i) -. py) /. dy in
      room.(hbase + (3 * i)) <- 1.;
      room.(hbase + (3 * i) + 1) <- k;
      room.(hbase + (3 * i) + 2) <- (k *. ((a *. k) +. b2)) +. c
    done
  else for i = 0 to nh - 1 do room.(hbase + (3 * i)) <- 0. done;
  for i = 0 to nr - 1 do
    let j = rbase + (5 * i) in
    room.(j) <- 0.;
    if b.radius.(i) > epsilon then begin
      let d = bb -. (a *. (c -. b.radius.(i))) in
      if d > 0. then begin
        let d = sqrt d in
        let k = (-.bb0 +. d) /. a in
        room.(j) <- 2.;
        room.(j + 1) <- k;
        room.(j + 2) <- py +. (k *. dy);
        let k = (-.bb0 -. d) /. a in
        room.(j + 3) <- k;
        room.(j + 4) <- py +. (k *. dy)
      end
    end
  done;
  (* each segment's thick cylinder, and its entry into the sorted list *)
  let cnt = ref 0 in
  let insert d0 n =
    let k = ref 0 in
    while !k < !cnt && d0 > room.(2 * !k) do incr k done;
    for m = !cnt downto !k + 1 do
      room.(2 * m) <- room.(2 * (m - 1));
      room.((2 * m) + 1) <- room.((2 * (m - 1)) + 1)
    done;
    room.(2 * !k) <- d0;
    room.((2 * !k) + 1) <- Float.of_int n;
    incr cnt
  in
  for i = 0 to number - 1 do
    let e = b.entry.(i) in
    let n = ref 0 in
    let add d = room.(dbase + !n) <- d; incr n in
    let rlo = b.radius.(e.r1) and rhi = b.radius.(e.r2) and hlo = b.height.(e.h1) and hhi = b.height.(e.h2) in
    let ring h =
      let j = hbase + (3 * h) in
      if room.(j) <> 0. then begin
        let r = room.(j + 2) in
        if r >= rlo && r <= rhi then add room.(j + 1)
      end
    in
    let wall r =
      let j = rbase + (5 * r) in
      if room.(j) <> 0. then begin
        let h = room.(j + 2) in
        if h >= hlo && h <= hhi then add room.(j + 1);
        let h = room.(j + 4) in
        if h >= hlo && h <= hhi then add room.(j + 3)
      end
    in
    ring e.h2;
    ring e.h1;
    wall e.r1;
    wall e.r2;
    let n = !n in
    for p = 0 to n - 1 do
      for q = 0 to n - p - 2 do
        let x = room.(dbase + q) and y = room.(dbase + q + 1) in
        if x > y then begin
          room.(dbase + q) <- y;
          room.(dbase + q + 1) <- x
        end
      done
    done;
    let dist k = room.(dbase + k) in
    match n with
    | 0 -> ()
    | 2 -> if dist 0 > epsilon then insert (dist 0) i else if dist 1 > epsilon then insert 0. i
    | 4 ->
        if dist 0 > epsilon then insert (dist 0) i
        else if dist 1 > epsilon then insert 0. i
        else if dist 2 > epsilon then insert (dist 2) i
        else if dist 3 > epsilon then insert 0. i
    | _ -> insert (dist 0) i
  done;
  !cnt

let interval_depth (w : Scratch.t) j = w.bcyl.room.(2 * j)
let interval_segment (w : Scratch.t) j = int_of_float w.bcyl.room.((2 * j) + 1)
