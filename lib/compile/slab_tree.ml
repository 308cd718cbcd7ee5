(* POV-Ray's bounding-slab tree (Build_BBox_Tree, sort_and_split; docs/povray-rules.md §15.8), built only for
   the order in which it lists its objects: POV-Ray fills the camera's starting interior list by
   walking this tree depth first (§6.4), so with the camera inside several objects that order
   decides which one counts as entered last. Boxes are POV-Ray's single-precision ones
   ([| llx; lly; llz; lx; ly; lz |], Shape.pov_box); the arithmetic keeps POV-Ray's precision
   at each step (float sums where it adds two floats, double elsewhere), and its sort is stable
   (glibc's qsort is a merge sort). *)

let f32 = Precision.f32
let bound_huge = 2e10

(* Objects are grouped at most this many to a node (BUNCHING_FACTOR). *)
let bunching = 4

type node = Leaf of int * float array | Node of node list * float array

let box = function Leaf (_, b) | Node (_, b) -> b

(* find_axis: the axis to sort along. POV-Ray's version records a box's LOWER corner as the
   maximum whenever the box's upper corner exceeds it, and this is kept. *)
let find_axis (items : node array) first last =
  let mins = Array.make 3 bound_huge and maxs = Array.make 3 (-.bound_huge) in
  for i = first to last - 1 do
    let b = box items.(i) in
    for a = 0 to 2 do
      if b.(a) < mins.(a) then mins.(a) <- b.(a);
      if f32 (b.(a) +. b.(a + 3)) > maxs.(a) then maxs.(a) <- b.(a)
    done
  done;
  let which = ref 0 and d = ref (-.bound_huge) in
  for a = 0 to 2 do
    let e = maxs.(a) -. mins.(a) in
    if e > !d then begin
      d := e;
      which := a
    end
  done;
  !which

(* calc_bbox over items [first, last): min and max in double, stored in single precision *)
let calc_box (items : node array) first last =
  let bmin = Array.make 3 bound_huge and bmax = Array.make 3 (-.bound_huge) in
  for i = first to last - 1 do
    let b = box items.(i) in
    for a = 0 to 2 do
      let tmin = b.(a) in
      let tmax = tmin +. b.(a + 3) in
      if tmin < bmin.(a) then bmin.(a) <- tmin;
      if tmax > bmax.(a) then bmax.(a) <- tmax
    done
  done;
  Array.init 6 (fun k -> if k < 3 then f32 bmin.(k) else f32 (bmax.(k - 3) -. bmin.(k - 3)))

(* build_area_table: the half surface area of the box around items a … i, for every i from a
   towards b, stored at i − min(a, b) *)
let area_table (items : node array) a b areas =
  let imin = min a b and dir = if a < b then 1 else -1 in
  let bmin = Array.make 3 bound_huge and bmax = Array.make 3 (-.bound_huge) in
  let i = ref a in
  while !i <> b + dir do
    let bx = box items.(!i) in
    for k = 0 to 2 do
      let tmin = bx.(k) in
      let tmax = tmin +. bx.(k + 3) in
      if tmin < bmin.(k) then bmin.(k) <- tmin;
      if tmax > bmax.(k) then bmax.(k) <- tmax
    done;
    let lx = bmax.(0) -. bmin.(0) and ly = bmax.(1) -. bmin.(1) and lz = bmax.(2) -. bmin.(2) in
    areas.(!i - imin) <- (lx *. (ly +. lz)) +. (ly *. lz);
    i := !i + dir
  done

(* [queued] is the tree the priority queue walks: where there are unbounded objects, POV-Ray
   moves them into a first node of the root and marks that node and the root infinite; an
   infinite node or leaf has the box [||]. [nodes] counts its nodes and leaves (the queue never
   holds more). *)
type t = { infinite : int list; root : node option; queued : node option; nodes : int }

let build (finite : (int * float array) list) (infinite : int list) =
  let items = ref (Array.of_list (List.map (fun (id, b) -> Leaf (id, b)) finite)) in
  let count = ref (Array.length !items) in
  let push n =
    if !count >= Array.length !items then items := Array.append !items (Array.make (max 4 !count) n);
    !items.(!count) <- n;
    incr count
  in
  let root = ref None in
  (* sort_and_split: true when [first, last) became a single node *)
  let rec split first last =
    let axis = find_axis !items first last in
    let size = last - first in
    let key n = let b = box n in f32 ((2.0 *. b.(axis)) +. b.(axis + 3)) in
    let sorted = Array.sub !items first size in
    Array.stable_sort (fun a b -> compare (key a) (key b)) sorted;
    Array.blit sorted 0 !items first size;
    let left = Array.make size 0. and right = Array.make size 0. in
    area_table !items first (last - 1) left;
    area_table !items (last - 1) first right;
    let best = ref (right.(0) *. (float_of_int size -. 3.0)) and best_loc = ref (-1) in
    for i = 0 to size - 2 do
      let v = (float_of_int (i + 1) *. left.(i)) +. (float_of_int (size - 1 - i) *. right.(i + 1)) in
      if v < !best then begin
        best := v;
        best_loc := i + first
      end
    done;
    if size <= bunching || !best_loc < 0 then begin
      let n = Node (Array.to_list (Array.sub !items first size), calc_box !items first last) in
      root := Some n;
      push n;
      true
    end
    else begin
      let b = !best_loc in
      ignore (split first (b + 1));
      ignore (split (b + 1) last);
      false
    end
  in
  if !count > 0 then begin
    let low = ref 0 and high = ref !count in
    while not (split !low !high) do
      low := !high;
      high := !count
    done
  end;
  let unbounded = Node (List.map (fun id -> Leaf (id, [||])) infinite, [||]) in
  let queued =
    match (!root, infinite) with
    | r, [] -> r
    | None, _ :: _ -> Some unbounded
    | Some (Node (ns, _)), _ :: _ -> Some (Node (unbounded :: ns, [||]))
    | Some (Leaf _ as l), _ :: _ -> Some (Node ([ unbounded; l ], [||]))
  in
  let rec count = function Leaf _ -> 1 | Node (ns, _) -> List.fold_left (fun n c -> n + count c) 1 ns in
  { infinite; root = !root; queued; nodes = (match queued with None -> 0 | Some q -> count q) }

let walk t in_box =
  let rec go acc = function
    | Leaf (id, b) -> if in_box b then id :: acc else acc
    | Node (ns, b) -> if in_box b then List.fold_left go acc ns else acc
  in
  let finite =
    match t.root with
    | None -> []
    | Some (Node (ns, _)) when t.infinite <> [] ->
        (* the infinite objects' node joins the root's children, and the root's box becomes
           unbounded: only its children's boxes are asked *)
        List.rev (List.fold_left go [] ns)
    | Some r -> List.rev (go [] r)
  in
  t.infinite @ finite

(* Priority queue depth of an infinite node or leaf (Check_And_Enqueue: −MAX_DISTANCE) *)
let infinite_depth = -1e7

(* POV-Ray's binary heap of (entry depth, node), 1-based (priority_queue_insert,
   Priority_Queue_Delete), with its exact moves: equal depths are ordered by the mechanics of
   the heap, not by insertion. *)
type heap = { mutable depths : float array; mutable held : node array; mutable size : int }

let insert h depth n =
  h.size <- h.size + 1;
  let i = ref h.size in
  while !i > 1 && depth < h.depths.(!i / 2) do
    h.depths.(!i) <- h.depths.(!i / 2);
    h.held.(!i) <- h.held.(!i / 2);
    i := !i / 2
  done;
  h.depths.(!i) <- depth;
  h.held.(!i) <- n

let pop h =
  let top = h.held.(1) in
  h.depths.(1) <- h.depths.(h.size);
  h.held.(1) <- h.held.(h.size);
  h.size <- h.size - 1;
  let size = h.size in
  let rec sift i =
    if 2 * i <= size then begin
      let j = if 2 * i = size || h.depths.(2 * i) < h.depths.((2 * i) + 1) then 2 * i else (2 * i) + 1 in
      if h.depths.(i) > h.depths.(j) then begin
        let d = h.depths.(i) and n = h.held.(i) in
        h.depths.(i) <- h.depths.(j);
        h.held.(i) <- h.held.(j);
        h.depths.(j) <- d;
        h.held.(j) <- n;
        sift j
      end
    end
  in
  sift 1;
  top

(* Intersect_BBox_Tree's walk: the root queued, then nodes popped nearest entry first, a node's
   children queued (Check_And_Enqueue: a node the ray's slabs miss is never queued), a leaf's id
   handed to [leaf], which says whether to stop; the walk stops too where the heap is empty or the
   node popped is entered beyond [limit ()]. *)
let traverse t h ri (o : Vec.t) (d : Vec.t) limit leaf =
  match t.queued with
  | None -> ()
  | Some root ->
      h.size <- 0;
      Pov_box.set_ray ri o d;
      let enqueue n =
        let bx = box n in
        let depth = if Array.length bx = 0 then infinite_depth else Pov_box.entry_from ri bx in
        if depth < infinity then insert h depth n
      in
      enqueue root;
      let rec next () =
        if h.size > 0 then begin
          let depth = h.depths.(1) in
          if not (depth > limit ()) then
            match pop h with
            | Leaf (id, _) -> if not (leaf id) then next ()
            | Node (ns, _) ->
                List.iter enqueue ns;
                next ()
        end
      in
      next ()

(* A walk's room: the heap, grown to the tree's size when a walk first needs it (it never holds
   more than every node), and the ray's slab data. *)
type room = { heap : heap; ray : Pov_box.ray_info }

let room () = { heap = { depths = [||]; held = [||]; size = 0 }; ray = Pov_box.ray_info () }

let search t room o d limit test =
  (match t.queued with
  | Some root when Array.length room.heap.depths < t.nodes + 1 ->
      room.heap.depths <- Array.make (t.nodes + 1) 0.;
      room.heap.held <- Array.make (t.nodes + 1) root
  | Some _ | None -> ());
  traverse t room.heap room.ray o d limit (fun id -> test id; false)
