(* Bvh: the hierarchy's traversal against a brute-force slab test over every primitive box, the
   root box, the pruning by the limit, and flat boxes. *)

open Helpers

let stack () = Array.make 512 0.

(* Boxes as (x0, y0, z0, x1, y1, z1) tuples, stored with set_box and built; the boxes returned are
   a copy made before the build (which reorders its argument). *)
let build_boxes (l : (float * float * float * float * float * float) list) =
  let prim = Bvh.create_boxes (List.length l) in
  List.iteri (fun i (x0, y0, z0, x1, y1, z1) -> Bvh.set_box prim i x0 y0 z0 x1 y1 z1) l;
  let kept = Bvh.create_boxes (List.length l) in
  Bigarray.Array1.blit prim kept;
  (kept, Bvh.build prim)

let range n = List.init n Fun.id

(* Cubes of side 0.8 at every integer point of [0, n)³, with gaps of 0.2; primitive
   i·n² + j·n + k is the cube at <i,j,k>. *)
let grid n =
  List.concat_map
    (fun i ->
      List.concat_map
        (fun j ->
          List.map
            (fun k ->
              let x = float_of_int i and y = float_of_int j and z = float_of_int k in
              (x, y, z, x +. 0.8, y +. 0.8, z +. 0.8))
            (range n))
        (range n))
    (range n)

(* Brute force: the distance at which the ray o + t·d, 0 ≤ t ≤ limit, enters the box b (6 floats),
   or None. A zero direction component needs o within the slab of that axis. *)
let slab_entry (b : float array) (o : float array) (d : float array) limit =
  let rec go a tn tf =
    if a = 3 then if tn <= tf then Some tn else None
    else if d.(a) = 0. then if o.(a) < b.(a) || o.(a) > b.(a + 3) then None else go (a + 1) tn tf
    else
      let t0 = (b.(a) -. o.(a)) /. d.(a) and t1 = (b.(a + 3) -. o.(a)) /. d.(a) in
      go (a + 1) (Float.max tn (Float.min t0 t1)) (Float.min tf (Float.max t0 t1))
  in
  go 0 0. limit

(* Primitive i's box as stored (widened and rounded to floats), a node's box. *)
let prim_box (prim : Bvh.f32s) i = Array.init 6 (fun q -> prim.{(6 * i) + q})
let node_box (t : Bvh.t) k = Array.init 6 (fun q -> t.boxes.{(6 * k) + q})
let count (prim : Bvh.f32s) = Bigarray.Array1.dim prim / 6

(* The leaves: (node, its primitives) for every node whose third link is −1. *)
let leaves (t : Bvh.t) =
  List.filter_map
    (fun k ->
      if t.links.{(3 * k) + 2} = -1l then
        let first = Int32.to_int t.links.{3 * k} and cnt = Int32.to_int t.links.{(3 * k) + 1} in
        Some (k, List.init cnt (fun j -> Int32.to_int t.order.{first + j}))
      else None)
    (range t.nodes)

let leaf_of t i = List.find (fun (_, ps) -> List.mem i ps) (leaves t)

(* The primitives walk visits, in order; [ret i limit] is what visit returns. *)
let walk ?(limit = infinity) ?(ret = fun _ l -> l) (t : Bvh.t) o d =
  let seen = ref [] in
  Bvh.walk t (stack ()) o.(0) o.(1) o.(2) d.(0) d.(1) d.(2) limit (fun i ->
      seen := i :: !seen;
      ret i limit);
  List.rev !seen

let sort_uniq l = List.sort_uniq compare l
let ints = Alcotest.(list int)

(* One walk against the brute force: every primitive whose box the ray meets before [limit] is
   visited, each visited primitive once, and the visited primitives are exactly those of the
   leaves whose box the ray meets before [limit] (walk visits a leaf whole). The number of
   primitive boxes crossed is returned. *)
let check_walk ?(limit = infinity) msg prim t o d =
  let visited = walk ~limit t o d in
  let crossed = List.filter (fun i -> slab_entry (prim_box prim i) o d limit <> None) (range (count prim)) in
  Alcotest.(check int) (msg ^ ": each visited once") (List.length (sort_uniq visited)) (List.length visited);
  List.iter (fun i -> if not (List.mem i visited) then Alcotest.failf "%s: primitive %d is crossed but not visited" msg i) crossed;
  let from_leaves = List.concat_map (fun (k, ps) -> if slab_entry (node_box t k) o d limit <> None then ps else []) (leaves t) in
  Alcotest.check ints (msg ^ ": the crossed leaves' primitives") (sort_uniq from_leaves) (sort_uniq visited);
  List.length crossed

(* ---- traversal against brute force ---- *)

let test_random_rays () =
  let prim, t = build_boxes (grid 5) in
  Alcotest.(check bool) "several nodes" true (t.nodes > 1);
  let rs = Random.State.make [| 2024 |] in
  let u lo hi = lo +. Random.State.float rs (hi -. lo) in
  let total = ref 0 and axis_total = ref 0 and inside_total = ref 0 in
  let dir zeros =
    (* a direction with the given axes set to zero, the others in [−1, 1] and not 0 *)
    Array.init 3 (fun a -> if List.mem a zeros then 0. else let x = u (-1.) 1. in if x = 0. then 0.5 else x)
  in
  for r = 0 to 2999 do
    let kind = r mod 6 in
    let zeros =
      match kind with
      | 0 | 1 -> []
      | 2 -> [ Random.State.int rs 3 ]
      | 3 -> (match Random.State.int rs 3 with 0 -> [ 1; 2 ] | 1 -> [ 0; 2 ] | _ -> [ 0; 1 ])
      | 4 -> []
      | _ -> [ Random.State.int rs 3 ]
    in
    let o =
      if kind >= 4 then
        (* inside a cube: its corner plus 0.05 … 0.75 on each axis *)
        Array.init 3 (fun _ -> float_of_int (Random.State.int rs 5) +. u 0.05 0.75)
      else Array.init 3 (fun _ -> u (-2.) 7.)
    in
    let d = dir zeros in
    let limit = if r mod 4 = 3 then u 0. 6. else infinity in
    let n = check_walk ~limit (Printf.sprintf "ray %d" r) prim t o d in
    total := !total + n;
    if zeros <> [] then axis_total := !axis_total + n;
    if kind >= 4 then inside_total := !inside_total + n
  done;
  (* the rays do cross boxes: the comparison is not vacuous *)
  Alcotest.(check bool) "boxes crossed" true (!total > 3000);
  Alcotest.(check bool) "boxes crossed by rays with zero components" true (!axis_total > 1000);
  Alcotest.(check bool) "boxes crossed from inside a box" true (!inside_total > 1000)

(* Every primitive in exactly one leaf; every box holds its children's (or its primitives') boxes. *)
let check_structure prim (t : Bvh.t) =
  let n = count prim in
  let seen = Array.make n 0 in
  let inside (outer : float array) (b : float array) =
    outer.(0) <= b.(0) && outer.(1) <= b.(1) && outer.(2) <= b.(2) && outer.(3) >= b.(3) && outer.(4) >= b.(4) && outer.(5) >= b.(5)
  in
  for k = 0 to t.nodes - 1 do
    let l = Int32.to_int t.links.{3 * k} and r = Int32.to_int t.links.{(3 * k) + 1} in
    if t.links.{(3 * k) + 2} = -1l then
      for j = l to l + r - 1 do
        let i = Int32.to_int t.order.{j} in
        seen.(i) <- seen.(i) + 1;
        if not (inside (node_box t k) (prim_box prim i)) then Alcotest.failf "leaf %d does not hold primitive %d" k i
      done
    else begin
      if l <= k || r <= k || l >= t.nodes || r >= t.nodes then Alcotest.failf "node %d has children %d and %d" k l r;
      if not (inside (node_box t k) (node_box t l) && inside (node_box t k) (node_box t r)) then
        Alcotest.failf "node %d does not hold its children" k
    end
  done;
  Array.iteri (fun i c -> if c <> 1 then Alcotest.failf "primitive %d is in %d leaves" i c) seen

(* More primitives than the SAH-only limit: the Morton-order top levels. *)
let test_large () =
  let prim, t = build_boxes (grid 17) in
  check_structure prim t;
  let rs = Random.State.make [| 7 |] in
  let u lo hi = lo +. Random.State.float rs (hi -. lo) in
  let total = ref 0 in
  for r = 0 to 199 do
    let o = Array.init 3 (fun _ -> u (-3.) 20.) in
    (* aimed at a point of the grid; every fifth ray with one zero component *)
    let target = Array.init 3 (fun _ -> u 0. 17.) in
    let d = Array.init 3 (fun a -> if r mod 5 = 0 && a = r mod 3 then 0. else target.(a) -. o.(a)) in
    let limit = if r mod 4 = 3 then u 0. 15. else infinity in
    total := !total + check_walk ~limit (Printf.sprintf "ray %d" r) prim t o d
  done;
  Alcotest.(check bool) "boxes crossed" true (!total > 1000)

let test_axis_rays () =
  let prim, t = build_boxes (grid 5) in
  (* along +x through the row j = 2, k = 3, from outside: the five cubes <i,2,3>, i = 0 … 4
     (primitives 25i + 13), met at t = i + 1 from x = −1 *)
  let o = [| -1.; 2.4; 3.4 |] and d = [| 1.; 0.; 0. |] in
  let visited = walk t o d in
  List.iter (fun i -> if not (List.mem ((25 * i) + 13) visited) then Alcotest.failf "cube <%d,2,3> missed" i) (range 5);
  ignore (check_walk "+x row" prim t o d);
  (* along −y from inside the cube <1,1,1> (primitive 31): it and <1,0,1> (primitive 26) *)
  let o = [| 1.4; 1.4; 1.4 |] and d = [| 0.; -1.; 0. |] in
  let visited = walk t o d in
  Alcotest.(check bool) "starting cube" true (List.mem 31 visited);
  Alcotest.(check bool) "cube below" true (List.mem 26 visited);
  Alcotest.(check int) "two boxes crossed" 2 (check_walk "-y from inside" prim t o d);
  (* a zero direction component with the origin exactly on a stored face of the box <2,2,3>
     (primitive 63): y = its stored minimum. The slab [y0, y1] contains y0, so the box is met;
     (y0 − oy)·(1/0) would be 0·∞ = NaN, which is why recip gives a finite number *)
  let y0 = (prim_box prim 63).(1) in
  let o = [| -1.; y0; 3.4 |] and d = [| 1.; 0.; 0. |] in
  Alcotest.(check bool) "origin on a face plane" true (List.mem 63 (walk t o d));
  ignore (check_walk "origin on a face plane" prim t o d);
  (* leaving a box 5e-4 after the start (x = 0.8 − 5e-4 in the cube <0,0,0>, along +x): still met,
     the ray starts at t = 0 *)
  Alcotest.(check bool) "leaving a box at once" true (List.mem 0 (walk t [| 0.8 -. 5e-4; 0.4; 0.4 |] [| 1.; 0.; 0. |]));
  (* the same at the edge of the whole grid: cube <4,0,0> (primitive 100), left at x = 4.8 *)
  Alcotest.(check bool) "leaving the root box at once" true (List.mem 100 (walk t [| 4.8 -. 5e-4; 0.4; 0.4 |] [| 1.; 0.; 0. |]));
  (* along +z in a gap (x = 0.9): no box is crossed *)
  Alcotest.(check int) "in a gap" 0 (check_walk "gap" prim t [| 0.9; 0.4; -1. |] [| 0.; 0.; 1. |])

(* ---- limits ---- *)

(* 64 cubes in a row along x: cube i spans [i, i + 0.8] × [0, 0.8]². From <-0.5,0.4,0.4> along +x
   cube i is entered at t = i + 0.5. *)
let row () = build_boxes (List.map (fun i -> let x = float_of_int i in (x, 0., 0., x +. 0.8, 0.8, 0.8)) (range 64))
let row_o = [| -0.5; 0.4; 0.4 |]
let row_d = [| 1.; 0.; 0. |]

let test_limit () =
  let prim, t = row () in
  (* limit 10.5: cubes 0 … 10 are entered by then (cube 10 at 10.5, a little earlier after the
     widening), cube 11 only at 11.5 *)
  let visited = walk ~limit:10.5 t row_o row_d in
  List.iter (fun i -> if not (List.mem i visited) then Alcotest.failf "cube %d missed" i) (range 11);
  Alcotest.(check int) "cubes entered before 10.5" 11 (check_walk ~limit:10.5 "limit 10.5" prim t row_o row_d);
  Alcotest.(check bool) "not every cube" true (List.length visited < 64);
  Alcotest.(check bool) "not the last cube" false (List.mem 63 visited);
  (* a limit before the first box: nothing *)
  Alcotest.check ints "limit 0.4" [] (walk ~limit:0.4 t row_o row_d);
  (* visit lowering the limit to the entry of the box it was given, as the nearest-hit search does:
     nearer boxes come first, so cube 0 comes first and the limit drops to 0.5; every other leaf
     starts at ≥ 1.5 and is skipped: exactly the primitives of cube 0's leaf are visited *)
  let entry i = Option.get (slab_entry (prim_box prim i) row_o row_d infinity) in
  let visited = walk ~ret:(fun i _ -> entry i) t row_o row_d in
  Alcotest.(check int) "cube 0 first" 0 (List.hd visited);
  Alcotest.check ints "only cube 0's leaf" (sort_uniq (snd (leaf_of t 0))) (sort_uniq visited);
  (* visit returning −∞ (any-hit) stops after the first leaf as well *)
  let visited = walk ~ret:(fun _ _ -> neg_infinity) t row_o row_d in
  Alcotest.check ints "any-hit: only cube 0's leaf" (sort_uniq (snd (leaf_of t 0))) (sort_uniq visited);
  (* from the other end, along −x: cube 63 first *)
  let o = [| 64.5; 0.4; 0.4 |] and d = [| -1.; 0.; 0. |] in
  let visited = walk ~ret:(fun i _ -> Option.get (slab_entry (prim_box prim i) o d infinity)) t o d in
  Alcotest.(check int) "cube 63 first" 63 (List.hd visited);
  Alcotest.check ints "only cube 63's leaf" (sort_uniq (snd (leaf_of t 63))) (sort_uniq visited)

(* ---- boxes ---- *)

let test_root_box () =
  let prim, t = build_boxes (grid 5) in
  for a = 0 to 2 do
    for i = 0 to count prim - 1 do
      let b = prim_box prim i in
      if Bvh.box_min t a > b.(a) || Bvh.box_max t a < b.(a + 3) then Alcotest.failf "primitive %d sticks out on axis %d" i a
    done;
    (* the root box is the union: from 0 (widened below 0) to 4.8 (widened above) *)
    let lo = Bvh.box_min t a and hi = Bvh.box_max t a in
    Alcotest.(check bool) (Printf.sprintf "axis %d: min in (−1e-6, 0]" a) true (lo <= 0. && lo > -1e-6);
    Alcotest.(check bool) (Printf.sprintf "axis %d: max in [4.8, 4.8 + 1e-6)" a) true (hi >= 4.8 && hi < 4.8 +. 1e-6);
    float_eq (Printf.sprintf "axis %d: min is the primitives' min" a) (List.fold_left Float.min infinity (List.map (fun i -> (prim_box prim i).(a)) (range 125))) lo
  done

let test_set_box () =
  let b = Bvh.create_boxes 2 in
  Bvh.set_box b 0 1. 1. 1. 1. 1. 1.;
  (* 1 − 1e-9 rounds to the float 1, which is above it: one float lower, 1 − 2⁻²⁴;
     1 + 1e-9 rounds to 1, below it: one float higher, 1 + 2⁻²³ *)
  float_eq ~eps:0. "1 widened down" (1. -. ldexp 1. (-24)) b.{0};
  float_eq ~eps:0. "1 widened up" (1. +. ldexp 1. (-23)) b.{3};
  Bvh.set_box b 1 0.1 (-0.1) 0. 0.1 (-0.1) 0.;
  let is_f32 x = Int32.float_of_bits (Int32.bits_of_float x) = x in
  for q = 0 to 5 do Alcotest.(check bool) (Printf.sprintf "value %d is a float" q) true (is_f32 b.{6 + q}) done;
  Alcotest.(check bool) "0.1 low side below 0.1" true (b.{6} < 0.1 && b.{6} > 0.1 -. 1e-7);
  Alcotest.(check bool) "0.1 high side above 0.1" true (b.{9} > 0.1 && b.{9} < 0.1 +. 1e-7);
  Alcotest.(check bool) "−0.1 low side below" true (b.{7} < -0.1 && b.{7} > -0.1 -. 1e-7);
  Alcotest.(check bool) "−0.1 high side above" true (b.{10} > -0.1 && b.{10} < -0.1 +. 1e-7);
  Alcotest.(check bool) "0 widened both ways" true (b.{8} < 0. && b.{11} > 0.)

let test_entry () =
  let _, t = build_boxes [ (0., 0., 0., 1., 1., 1.) ] in
  Alcotest.(check int) "one node" 1 t.nodes;
  let r = Bvh.recip in
  float_eq ~eps:0. "recip 2" 0.5 (r 2.);
  Alcotest.(check bool) "recip 0 is finite and huge" true (Float.is_finite (r 0.) && r 0. > 1e30);
  (* from <-1,0.5,0.5> along +x: the box (from just below 0) is entered at 1 *)
  float_eq ~eps:1e-6 "entered at 1" 1. (Bvh.entry t 0 (-1.) 0.5 0.5 (r 1.) (r 0.) (r 0.) 0. infinity);
  Alcotest.(check bool) "tmax 0.5 is before it" true (Bvh.entry t 0 (-1.) 0.5 0.5 (r 1.) (r 0.) (r 0.) 0. 0.5 = infinity);
  float_eq "from inside: tmin" 0. (Bvh.entry t 0 0.5 0.5 0.5 (r 1.) (r 0.) (r 0.) 0. infinity);
  Alcotest.(check bool) "pointing away" true (Bvh.entry t 0 2. 0.5 0.5 (r 1.) (r 0.) (r 0.) 0. infinity = infinity);
  Alcotest.(check bool) "beside it, parallel" true (Bvh.entry t 0 (-1.) 2. 0.5 (r 1.) (r 0.) (r 0.) 0. infinity = infinity);
  (* diagonal <1,1,1> from <-1,-1,-1>: every slab entered at 1 *)
  float_eq ~eps:1e-6 "diagonal" 1. (Bvh.entry t 0 (-1.) (-1.) (-1.) 1. 1. 1. 0. infinity)

let test_empty () =
  let _, t = build_boxes [] in
  Alcotest.(check int) "no nodes" 0 t.nodes;
  Alcotest.check ints "walk visits nothing" [] (walk t [| 0.; 0.; 0. |] [| 1.; 0.; 0. |])

let test_flat_boxes () =
  (* 100 squares [i, i + 0.9] × [j, j + 0.9] in the plane z = 0, zero thickness; primitive 10i + j *)
  let sq = List.concat_map (fun i -> List.map (fun j -> let x = float_of_int i and y = float_of_int j in (x, y, 0., x +. 0.9, y +. 0.9, 0.)) (range 10)) (range 10) in
  let prim, t = build_boxes sq in
  for i = 0 to 9 do
    for j = 0 to 9 do
      let x = float_of_int i +. 0.45 and y = float_of_int j +. 0.45 in
      let up = walk t [| x; y; -1. |] [| 0.; 0.; 1. |] and down = walk t [| x; y; 1. |] [| 0.; 0.; -1. |] in
      if not (List.mem ((10 * i) + j) up) then Alcotest.failf "square %d,%d missed from below" i j;
      if not (List.mem ((10 * i) + j) down) then Alcotest.failf "square %d,%d missed from above" i j
    done
  done;
  (* a ray lying in the plane z = 0, along +x through the row j = 4: all ten squares of the row *)
  let o = [| -1.; 4.45; 0. |] and d = [| 1.; 0.; 0. |] in
  let visited = walk t o d in
  List.iter (fun i -> if not (List.mem ((10 * i) + 4) visited) then Alcotest.failf "in-plane ray missed square %d,4" i) (range 10);
  Alcotest.(check int) "in-plane: ten crossed" 10 (check_walk "in plane" prim t o d);
  (* oblique: from <2.45,3.45,-1> along <0.25,0.25,1> meets z = 0 at t = 1, <2.7,3.7,0>, in square 2,3 *)
  let visited = walk t [| 2.45; 3.45; -1. |] [| 0.25; 0.25; 1. |] in
  Alcotest.(check bool) "oblique" true (List.mem 23 visited);
  (* flat boxes at z = 2 (not zero: widened by a relative amount) *)
  let prim, t = build_boxes [ (0., 0., 2., 1., 1., 2.); (3., 0., 2., 4., 1., 2.) ] in
  Alcotest.check ints "z = 2, from below" [ 1 ] (List.filter (( = ) 1) (walk t [| 3.5; 0.5; 0. |] [| 0.; 0.; 1. |]));
  Alcotest.(check int) "z = 2, in the plane" 2 (check_walk "z = 2 plane" prim t [| -1.; 0.5; 2. |] [| 1.; 0.; 0. |]);
  (* a segment (flat on two axes) along x at y = z = 1, crossed by a ray along +y *)
  let _, t = build_boxes [ (0., 1., 1., 1., 1., 1.) ] in
  Alcotest.check ints "segment" [ 0 ] (walk t [| 0.5; -1.; 1. |] [| 0.; 1.; 0. |])

let test_renumber () =
  let prim, t = build_boxes (grid 3) in
  let t', perm = Bvh.renumber t in
  Alcotest.check ints "perm is a permutation" (range 27) (sort_uniq (Array.to_list perm));
  Alcotest.check ints "perm is the old leaf order" (List.init 27 (fun j -> Int32.to_int t.order.{j})) (Array.to_list perm);
  let o = [| -1.; 1.4; 1.4 |] and d = [| 1.; 0.; 0. |] in
  Alcotest.check ints "same primitives, renamed" (sort_uniq (walk t o d)) (sort_uniq (List.map (fun j -> perm.(j)) (walk t' o d)));
  ignore prim

(* A primitive whose box is infinite (a sphere of radius -1e400) has a NaN centre. The centres'
   bounds are taken with comparisons that NaN fails, so they can leave out the centres read before
   it, and the build indexed its bins with a negative number for those (memory corruption under
   -unsafe; found by the fuzzer). Every primitive must still be in exactly one leaf. *)
let test_non_finite_boxes () =
  let inf = infinity in
  let whole = (-.inf, -.inf, -.inf, inf, inf, inf) and far = (-1e6, 0., 0., -1e6 +. 1., 1., 1.) in
  List.iter
    (fun boxes ->
      let n = List.length boxes in
      let _, t = build_boxes boxes in
      Alcotest.check ints "every primitive in one leaf" (range n) (List.sort compare (List.concat_map snd (leaves t))))
    [ (far :: whole :: grid 2); grid 2 @ [ whole; far ]; List.init 9 (fun _ -> whole) @ grid 2; [ far; whole; far; whole; far; whole ] ]

let tests =
  [
    Alcotest.test_case "random rays vs brute force" `Quick test_random_rays;
    Alcotest.test_case "axis-parallel rays" `Quick test_axis_rays;
    Alcotest.test_case "limit" `Quick test_limit;
    Alcotest.test_case "root box" `Quick test_root_box;
    Alcotest.test_case "set_box" `Quick test_set_box;
    Alcotest.test_case "entry" `Quick test_entry;
    Alcotest.test_case "empty" `Quick test_empty;
    Alcotest.test_case "flat boxes" `Quick test_flat_boxes;
    Alcotest.test_case "4913 boxes: Morton-order top, structure and rays" `Quick test_large;
    Alcotest.test_case "renumber" `Quick test_renumber;
    Alcotest.test_case "infinite and NaN boxes" `Quick test_non_finite_boxes;
  ]
