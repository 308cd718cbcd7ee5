(* The bounding sphere hierarchy of a blob's elements (bounding/bsphere.cpp,
   Build_Bounding_Sphere_Hierarchy), flattened into arrays. *)

let epsilon = Precision.epsilon
let bound_huge = 2e10

type t = {
  cx : float array;
  cy : float array;
  cz : float array;
  r2 : float array;
  entries : int array;  (** 0 for a leaf *)
  first : int array;  (** a leaf's element, a node's first child in [kids] *)
  kids : int array;
  root : int;  (** −1: no hierarchy *)
}

type bnode = { bc : Vec.t; br2 : float; bkids : bnode array; belem : int }

let merge_spheres (c1 : Vec.t) r1 (c2 : Vec.t) r2 =
  let d = Vec.sub c1 c2 in
  let l = sqrt ((d.x *. d.x) +. (d.y *. d.y) +. (d.z *. d.z)) in
  let r1r = sqrt r1 and r2r = sqrt r2 in
  if l +. r1r <= r2r then (c2, r2)
  else if l +. r2r <= r1r then (c1, r1)
  else
    let k1 = (1.0 +. ((r1r -. r2r) /. l)) /. 2.0 and k2 = (1.0 +. ((r2r -. r1r) /. l)) /. 2.0 in
    let c = Vec.make ((k1 *. c1.x) +. (k2 *. c2.x)) ((k1 *. c1.y) +. (k2 *. c2.y)) ((k1 *. c1.z) +. (k2 *. c2.z)) in
    let s = (l +. r1r +. r2r) /. 2.0 in
    (c, s *. s)

let axis_of (v : Vec.t) = function 0 -> v.x | 1 -> v.y | _ -> v.z

(* glibc's qsort (a stable top-down merge sort) with bsphere.cpp's comparison, equal within EPSILON *)
let msort (a : bnode array) first n axis =
  let cmp x y =
    let am = axis_of x.bc axis and bm = axis_of y.bc axis in
    if am < bm -. epsilon then -1 else if am > bm +. epsilon then 1 else 0
  in
  let tmp = Array.make (max n 1) a.(first) in
  let rec sort b n =
    if n > 1 then begin
      let n1 = n / 2 in
      let n2 = n - n1 in
      sort b n1;
      sort (b + n1) n2;
      let i = ref b and j = ref (b + n1) and k = ref 0 in
      let e1 = b + n1 and e2 = b + n in
      while !i < e1 && !j < e2 do
        if cmp a.(!i) a.(!j) <= 0 then (tmp.(!k) <- a.(!i); incr i) else (tmp.(!k) <- a.(!j); incr j);
        incr k
      done;
      while !i < e1 do
        tmp.(!k) <- a.(!i);
        incr i;
        incr k
      done;
      Array.blit tmp 0 a b !k
    end
  in
  sort first n

let find_axis (a : bnode array) first last =
  let mins = [| bound_huge; bound_huge; bound_huge |] and maxs = [| -.bound_huge; -.bound_huge; -.bound_huge |] in
  for i = first to last - 1 do
    let c = a.(i).bc in
    mins.(0) <- Float.min mins.(0) c.x;
    maxs.(0) <- Float.max maxs.(0) c.x;
    mins.(1) <- Float.min mins.(1) c.y;
    maxs.(1) <- Float.max maxs.(1) c.y;
    mins.(2) <- Float.min mins.(2) c.z;
    maxs.(2) <- Float.max maxs.(2) c.z
  done;
  let d = ref (-.bound_huge) and which = ref 0 in
  let e = maxs.(0) -. mins.(0) in
  if e > !d then (d := e; which := 0);
  let e = maxs.(1) -. mins.(1) in
  if e > !d then (d := e; which := 1);
  let e = maxs.(2) -. mins.(2) in
  if e > !d then which := 2;
  !which

(* build_area_table: the squared radii of the spheres merged from [a] towards [b] *)
let area_table (el : bnode array) a b areas =
  let imin, dir = if a < b then (a, 1) else (b, -1) in
  let c = ref el.(a).bc and r2 = ref el.(a).br2 in
  let i = ref a in
  while !i <> b + dir do
    let c', r2' = merge_spheres !c !r2 el.(!i).bc el.(!i).br2 in
    c := c';
    r2 := r2';
    areas.(!i - imin) <- !r2;
    i := !i + dir
  done

let build_hierarchy (leaves : bnode list) =
  let el = ref (Array.of_list leaves) in
  let n = ref (Array.length !el) in
  let root = ref None in
  let append node =
    if !n >= Array.length !el then begin
      let bigger = Array.make (max 1 (2 * Array.length !el)) node in
      Array.blit !el 0 bigger 0 !n;
      el := bigger
    end;
    !el.(!n) <- node;
    incr n
  in
  let rec sort_and_split first last =
    let axis = find_axis !el first last in
    let size = last - first in
    if size <= 0 then 1
    else begin
      msort !el first size axis;
      let left = Array.make size 0. and right = Array.make size 0. in
      area_table !el first (last - 1) left;
      area_table !el (last - 1) first right;
      let best_index = ref (right.(0) *. (Float.of_int size -. 3.0)) and best_loc = ref (-1) in
      for i = 0 to size - 2 do
        let ni = (Float.of_int (i + 1) *. left.(i)) +. (Float.of_int (size - 1 - i) *. right.(i + 1)) in
        if ni < !best_index then begin
          best_index := ni;
          best_loc := i + first
        end
      done;
      if size <= 4 || !best_loc < 0 then begin
        let kids = Array.sub !el first size in
        (* recompute_bound *)
        let c = ref kids.(0).bc and r2 = ref kids.(0).br2 in
        for i = 1 to size - 1 do
          let c', r2' = merge_spheres !c !r2 kids.(i).bc kids.(i).br2 in
          c := c';
          r2 := r2'
        done;
        let node = { bc = !c; br2 = !r2; bkids = kids; belem = -1 } in
        root := Some node;
        append node;
        1
      end
      else begin
        let loc = !best_loc in
        ignore (sort_and_split first (loc + 1));
        ignore (sort_and_split (loc + 1) last);
        0
      end
    end
  in
  if !n > 0 then begin
    let low = ref 0 and high = ref !n in
    while sort_and_split !low !high = 0 do
      low := !high;
      high := !n
    done
  end;
  !root

let none = { cx = [||]; cy = [||]; cz = [||]; r2 = [||]; entries = [||]; first = [||]; kids = [||]; root = -1 }

type numbered = Numbered of int * numbered array

let flatten (root : bnode) =
  let nodes = ref [] and count = ref 0 in
  let rec number (b : bnode) =
    let id = !count in
    incr count;
    nodes := (id, b) :: !nodes;
    Numbered (id, Array.map number b.bkids)
  in
  let ids = number root in
  let total = !count in
  let cx = Array.make total 0. and cy = Array.make total 0. and cz = Array.make total 0. and r2 = Array.make total 0. in
  let entries = Array.make total 0 and first = Array.make total 0 and kids = ref [] and nkids = ref 0 in
  List.iter
    (fun (id, (b : bnode)) ->
      cx.(id) <- b.bc.x;
      cy.(id) <- b.bc.y;
      cz.(id) <- b.bc.z;
      r2.(id) <- b.br2;
      if Array.length b.bkids = 0 then (entries.(id) <- 0; first.(id) <- b.belem))
    !nodes;
  let rec link (Numbered (id, sub)) =
    let k = Array.length sub in
    if k > 0 then begin
      entries.(id) <- k;
      first.(id) <- !nkids;
      Array.iter (fun (Numbered (c, _)) -> kids := c :: !kids) sub;
      nkids := !nkids + k;
      Array.iter link sub
    end
  in
  link ids;
  { cx; cy; cz; r2; entries; first; kids = Array.of_list (List.rev !kids); root = (match ids with Numbered (id, _) -> id) }

let build (spheres : (Vec.t * float) array) =
  let leaves = Array.to_list (Array.mapi (fun i (c, r2) -> { bc = c; br2 = r2; bkids = [||]; belem = i }) spheres) in
  match build_hierarchy leaves with None -> none | Some root -> flatten root
