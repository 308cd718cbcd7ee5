(* A bounding-volume hierarchy built with the binned surface-area heuristic and stored flat, in
   single precision outside the OCaml heap: node boxes (rounded outwards, as POV-Ray's bounding
   boxes are single precision too), node links and the primitive order. Traversal allocates
   nothing. *)

open Bigarray

type f32s = (float, float32_elt, c_layout) Array1.t
type i32s = (int32, int32_elt, c_layout) Array1.t

type t = {
  boxes : f32s;  (* 6 per node: min x y z, max x y z *)
  links : i32s;  (* 3 per node: leaf: first, count, -1; inner: left, right, split axis *)
  order : i32s;  (* primitive indices, leaves refer to ranges of this array *)
  nodes : int;
}

let[@inline] fget (a : f32s) i = Array1.unsafe_get a i
let[@inline] iget (a : i32s) i = Int32.to_int (Array1.unsafe_get a i)
let[@inline] iset (a : i32s) i x = Array1.unsafe_set a i (Int32.of_int x)

let f32 = Precision.f32

(* The single-precision value nearest below (above) x. *)
let f32_down x =
  let r = f32 x in
  if r <= x then r
  else if r > 0. then Int32.float_of_bits (Int32.pred (Int32.bits_of_float r))
  else if r < 0. then Int32.float_of_bits (Int32.succ (Int32.bits_of_float r))
  else -1.4e-45

let f32_up x = -.f32_down (-.x)

let create_boxes n = Array1.create float32 c_layout (6 * n)

(* Store primitive [i]'s box, widened by a relative 1e-9 and rounded outwards to single precision,
   so that no rounding in the slab test loses a hit on a flat (zero-thickness) box. *)
let set_box (b : f32s) i x0 y0 z0 x1 y1 z1 =
  let lo v = f32_down (v -. ((1e-9 *. Float.abs v) +. 1e-300)) and hi v = f32_up (v +. ((1e-9 *. Float.abs v) +. 1e-300)) in
  let o = 6 * i in
  Array1.unsafe_set b o (lo x0);
  Array1.unsafe_set b (o + 1) (lo y0);
  Array1.unsafe_set b (o + 2) (lo z0);
  Array1.unsafe_set b (o + 3) (hi x1);
  Array1.unsafe_set b (o + 4) (hi y1);
  Array1.unsafe_set b (o + 5) (hi z1)

let bins = 16

(* fmin/max also order −0 and NaN, which costs a C call; boxes need neither. *)
let[@inline] fmin (a : float) b = if a < b then a else b
let[@inline] fmax (a : float) b = if a > b then a else b
let[@inline] imin (a : int) b = if a < b then a else b
let leaf_size = 4

(* Hierarchies over at most [sah_all] primitives are built by the binned SAH alone; larger ones
   by Morton-order splits down to ranges of at most [sah_cluster] primitives, which the SAH then
   splits into leaves. *)
let sah_all = 4096
let sah_cluster = 16

let empty = { boxes = create_boxes 0; links = Array1.create int32 c_layout 0; order = Array1.create int32 c_layout 0; nodes = 0 }

(* Surface area (half of it; only ratios matter) of a box given as six floats. *)
let half_area x0 y0 z0 x1 y1 z1 =
  let dx = x1 -. x0 and dy = y1 -. y0 and dz = z1 -. z0 in
  if dx < 0. then 0. else (dx *. dy) +. (dy *. dz) +. (dz *. dx)

(* [build] permutes [prim] along with [order], so that the primitives of a node lie together in
   memory while the tree is built; callers do not use the boxes afterwards. Each node receives its
   box and the bounds of its primitives' centres from its parent (the bins of the parent's split
   hold both), so a level of the tree costs one binning pass and one partition pass. *)
let build (prim : f32s) =
  (* [prim] holds 6 values per primitive: its box, as [set_box] stores it *)
  let n = Array1.dim prim / 6 in
  if n = 0 then empty
  else begin
    let order = Array1.create int32 c_layout n in
    for i = 0 to n - 1 do iset order i i done;
    let[@inline] centre k a = 0.5 *. (fget prim ((6 * k) + a) +. fget prim ((6 * k) + 3 + a)) in
    let swap i j =
      let t = iget order i in
      iset order i (iget order j); iset order j t;
      let oi = 6 * i and oj = 6 * j in
      for q = 0 to 5 do
        let v = fget prim (oi + q) in
        Array1.unsafe_set prim (oi + q) (fget prim (oj + q));
        Array1.unsafe_set prim (oj + q) v
      done
    in
    (* room for the nodes grows as needed: leaves hold up to [leaf_size] primitives, so a tree
       usually has fewer than n nodes and the worst case (2n − 1) is rare *)
    let boxes_r = ref (create_boxes (n + 1)) and links_r = ref (Array1.create int32 c_layout (3 * (n + 1))) in
    let count = ref 0 in
    let reserve id =
      if 3 * (id + 1) > Array1.dim !links_r then begin
        let grow : 'a 'b. ('a, 'b, c_layout) Array1.t -> ('a, 'b, c_layout) Array1.t =
         fun a ->
          let len = Array1.dim a in
          let b = Array1.create (Array1.kind a) c_layout (len + (len / 2)) in
          Array1.blit a (Array1.sub b 0 len);
          b
        in
        boxes_r := grow !boxes_r;
        links_r := grow !links_r
      end
    in
    (* bounds: 12 floats, the box (min x y z, max x y z) then the centres' bounds likewise *)
    let empty_bounds () = [| infinity; infinity; infinity; neg_infinity; neg_infinity; neg_infinity; infinity; infinity; infinity; neg_infinity; neg_infinity; neg_infinity |] in
    (* widen the bounds at r.(at .. at + 11) by primitive k *)
    let[@inline] add_prim (r : float array) at k =
      let o = 6 * k in
      for q = 0 to 2 do
        let lo = fget prim (o + q) and hi = fget prim (o + 3 + q) in
        r.(at + q) <- fmin r.(at + q) lo;
        r.(at + 3 + q) <- fmax r.(at + 3 + q) hi;
        let c = 0.5 *. (lo +. hi) in
        r.(at + 6 + q) <- fmin r.(at + 6 + q) c;
        r.(at + 9 + q) <- fmax r.(at + 9 + q) c
      done
    in
    let bounds first cnt =
      let r = empty_bounds () in
      for k = first to first + cnt - 1 do add_prim r 0 k done;
      r
    in
    (* 12 floats per bin, as [bounds] *)
    let bin_b = Array.make (12 * bins) 0. and bin_n = Array.make bins 0 in
    let right_area = Array.make bins 0. and right_n = Array.make bins 0 in
    let union_bins j0 j1 =
      let r = empty_bounds () in
      for j = j0 to j1 - 1 do
        for q = 0 to 2 do
          r.(q) <- fmin r.(q) bin_b.((12 * j) + q);
          r.(3 + q) <- fmax r.(3 + q) bin_b.((12 * j) + 3 + q);
          r.(6 + q) <- fmin r.(6 + q) bin_b.((12 * j) + 6 + q);
          r.(9 + q) <- fmax r.(9 + q) bin_b.((12 * j) + 9 + q)
        done
      done;
      r
    in
    let rec node first cnt (bd : float array) =
      let id = !count in
      incr count;
      reserve id;
      let boxes = !boxes_r and links = !links_r in
      for q = 0 to 5 do Array1.unsafe_set boxes ((6 * id) + q) bd.(q) done;
      let leaf () = iset links (3 * id) first; iset links ((3 * id) + 1) cnt; iset links ((3 * id) + 2) (-1) in
      let inner axis nl lb rb =
        iset links ((3 * id) + 2) axis;
        let l = node first nl lb in
        let r = node (first + nl) (cnt - nl) rb in
        iset !links_r (3 * id) l; iset !links_r ((3 * id) + 1) r
      in
      let ext a = bd.(9 + a) -. bd.(6 + a) in
      let widest = if ext 0 >= ext 1 && ext 0 >= ext 2 then 0 else if ext 1 >= ext 2 then 1 else 2 in
      (if cnt <= leaf_size then leaf ()
          else begin
            (* binned SAH, along the axis where the centres spread most *)
            let best_cost = ref infinity and best_split = ref 0 in
            let a = widest in
            let lo = bd.(6 + a) and hi = bd.(9 + a) in
            let scale = float_of_int bins /. (hi -. lo) in
            (* clamped at both ends: a NaN centre (an infinite box) leaves the centres' bounds
               without the centres compared before it, and int_of_float of NaN is min_int *)
            let[@inline] bin_of k = let j = int_of_float ((centre k a -. lo) *. scale) in if j < 0 then 0 else imin (bins - 1) j in
            if hi > lo then begin
              for j = 0 to bins - 1 do
                bin_n.(j) <- 0;
                for q = 0 to 2 do
                  bin_b.((12 * j) + q) <- infinity; bin_b.((12 * j) + 3 + q) <- neg_infinity;
                  bin_b.((12 * j) + 6 + q) <- infinity; bin_b.((12 * j) + 9 + q) <- neg_infinity
                done
              done;
              for k = first to first + cnt - 1 do
                let j = bin_of k in
                bin_n.(j) <- bin_n.(j) + 1;
                add_prim bin_b (12 * j) k
              done;
              (* sweep from the right, then from the left *)
              let acc = Array.make 6 0. in
              let reset () = acc.(0) <- infinity; acc.(1) <- infinity; acc.(2) <- infinity; acc.(3) <- neg_infinity; acc.(4) <- neg_infinity; acc.(5) <- neg_infinity in
              let grow j = for q = 0 to 2 do acc.(q) <- fmin acc.(q) bin_b.((12 * j) + q); acc.(3 + q) <- fmax acc.(3 + q) bin_b.((12 * j) + 3 + q) done in
              reset ();
              let rn = ref 0 in
              for j = bins - 1 downto 1 do
                grow j;
                rn := !rn + bin_n.(j);
                right_n.(j) <- !rn;
                right_area.(j) <- half_area acc.(0) acc.(1) acc.(2) acc.(3) acc.(4) acc.(5)
              done;
              reset ();
              let ln = ref 0 in
              for j = 0 to bins - 2 do
                grow j;
                ln := !ln + bin_n.(j);
                if !ln > 0 && right_n.(j + 1) > 0 then begin
                  let cost = (half_area acc.(0) acc.(1) acc.(2) acc.(3) acc.(4) acc.(5) *. float_of_int !ln) +. (right_area.(j + 1) *. float_of_int right_n.(j + 1)) in
                  if cost < !best_cost then begin best_cost := cost; best_split := j + 1 end
                end
              done
            end;
            let found = !best_cost < infinity in
            let parent_cost = half_area bd.(0) bd.(1) bd.(2) bd.(3) bd.(4) bd.(5) *. float_of_int cnt in
            if (not found) || (!best_cost >= parent_cost && cnt <= 8) then
              if (not found) && cnt > leaf_size then begin
                (* all centres coincide: split in the middle of the list *)
                let half = cnt / 2 in
                inner 0 half (bounds first half) (bounds (first + half) (cnt - half))
              end
              else leaf ()
            else begin
              let split = !best_split in
              let lb = union_bins 0 split and rb = union_bins split bins in
              let i = ref first and j = ref (first + cnt - 1) in
              while !i <= !j do
                if bin_of !i < split then incr i
                else begin swap !i !j; decr j end
              done;
              inner a (!i - first) lb rb
            end
          end);
      id
    in
    (* Large hierarchies: the top levels by Morton order (a linear BVH). The centres are
       quantised to a 1024³ grid over the cube around their bounds, the primitives sorted by the
       interleaved bits (a stable radix sort) and every range split where its highest differing
       bit changes: the middle of a grid cell, found by binary search, so a level costs no pass
       over the primitives. On the meshes and object fields this is for, the result traces as
       fast as a full SAH tree, which costs several times more to build. *)
    if n <= sah_all then ignore (node 0 n (bounds 0 n))
    else begin
      let bd = bounds 0 n in
      let ext = fmax (bd.(9) -. bd.(6)) (fmax (bd.(10) -. bd.(7)) (bd.(11) -. bd.(8))) in
      let scale = if ext > 0. then 1024. /. ext else 0. in
      (* spread the 10 low bits of x to every third bit *)
      let spread x =
        let x = (x lor (x lsl 16)) land 0x030000FF in
        let x = (x lor (x lsl 8)) land 0x0300F00F in
        let x = (x lor (x lsl 4)) land 0x030C30C3 in
        (x lor (x lsl 2)) land 0x09249249
      in
      let q k a = let v = int_of_float ((centre k a -. bd.(6 + a)) *. scale) in if v < 0 then 0 else if v > 1023 then 1023 else v in
      (* key: the 30-bit code above the primitive's index *)
      let keys = Array.init n (fun k -> (((spread (q k 0) lsl 2) lor (spread (q k 1) lsl 1) lor spread (q k 2)) lsl 32) lor k) in
      let tmp = Array.make n 0 in
      let counts = Array.make 1024 0 in
      let src = ref keys and dst = ref tmp in
      List.iter
        (fun shift ->
          let s = !src and d = !dst in
          Array.fill counts 0 1024 0;
          for k = 0 to n - 1 do let b = (s.(k) lsr shift) land 1023 in counts.(b) <- counts.(b) + 1 done;
          let sum = ref 0 in
          for b = 0 to 1023 do let c = counts.(b) in counts.(b) <- !sum; sum := !sum + c done;
          for k = 0 to n - 1 do
            let b = (s.(k) lsr shift) land 1023 in
            d.(counts.(b)) <- s.(k);
            counts.(b) <- counts.(b) + 1
          done;
          src := d; dst := s)
        [ 32; 42; 52 ];
      let keys = !src and spare = !dst in
      (* move the boxes into sorted order, cycle by cycle (a moved slot is marked in [moved]) *)
      let mask = (1 lsl 32) - 1 in
      let from j = keys.(j) land mask in
      let moved = spare in
      Array.fill moved 0 n 0;
      let saved = Array.make 6 0. in
      for j = 0 to n - 1 do
        if moved.(j) = 0 && from j <> j then begin
          for q = 0 to 5 do saved.(q) <- fget prim ((6 * j) + q) done;
          let k = ref j in
          while from !k <> j do
            let f = from !k in
            for q = 0 to 5 do Array1.unsafe_set prim ((6 * !k) + q) (fget prim ((6 * f) + q)) done;
            moved.(!k) <- 1;
            k := f
          done;
          for q = 0 to 5 do Array1.unsafe_set prim ((6 * !k) + q) saved.(q) done;
          moved.(!k) <- 1
        end
      done;
      for j = 0 to n - 1 do iset order j (from j) done;
      let code j = keys.(j) lsr 32 in
      let rec lnode first cnt =
        if cnt <= sah_cluster then node first cnt (bounds first cnt)
        else begin
          let id = !count in
          incr count;
          reserve id;
          let last = first + cnt - 1 in
          let x = code first lxor code last in
          let nl, axis =
            if x = 0 then (cnt / 2, 0)
            else begin
              (* the highest differing bit, then the first code that has it *)
              let bit = ref 29 in
              while x land (1 lsl !bit) = 0 do decr bit done;
              let lo = ref first and hi = ref last in
              while !lo < !hi do
                let m = (!lo + !hi) / 2 in
                if code m land (1 lsl !bit) <> 0 then hi := m else lo := m + 1
              done;
              (!lo - first, 2 - (!bit mod 3))
            end
          in
          iset !links_r ((3 * id) + 2) axis;
          let l = lnode first nl in
          let r = lnode (first + nl) (cnt - nl) in
          let links = !links_r and boxes = !boxes_r in
          iset links (3 * id) l; iset links ((3 * id) + 1) r;
          for q = 0 to 2 do
            Array1.unsafe_set boxes ((6 * id) + q) (fmin (fget boxes ((6 * l) + q)) (fget boxes ((6 * r) + q)));
            Array1.unsafe_set boxes ((6 * id) + 3 + q) (fmax (fget boxes ((6 * l) + 3 + q)) (fget boxes ((6 * r) + 3 + q)))
          done;
          id
        end
      in
      ignore (lnode 0 n)
    end;
    (* the arrays may be longer than the nodes need; [nodes] says how many are used *)
    { boxes = !boxes_r; links = !links_r; order; nodes = !count }
  end

(* Slab test of node [k] against the ray (origin o, reciprocal direction id, where a zero direction
   component has a huge finite reciprocal); the entry distance when the box is met between [tmin]
   and [tmax], else infinity. *)
let[@inline] entry t k ox oy oz idx idy idz tmin tmax =
  let b = t.boxes and o = 6 * k in
  let tx0 = (fget b o -. ox) *. idx and tx1 = (fget b (o + 3) -. ox) *. idx in
  let ty0 = (fget b (o + 1) -. oy) *. idy and ty1 = (fget b (o + 4) -. oy) *. idy in
  let tz0 = (fget b (o + 2) -. oz) *. idz and tz1 = (fget b (o + 5) -. oz) *. idz in
  let near = fmax (fmax (fmin tx0 tx1) (fmin ty0 ty1)) (fmax (fmin tz0 tz1) tmin) in
  let far = fmin (fmin (fmax tx0 tx1) (fmax ty0 ty1)) (fmin (fmax tz0 tz1) tmax) in
  if near <= far then near else infinity

let recip x = if x = 0. then 1e300 else 1. /. x

(* Visit the primitives whose boxes the ray meets, nearer boxes first: [visit state i] for each,
   which may lower the limit in [lim.(0)] beyond which boxes are skipped. The visitor and its state
   are passed apart, so that a caller whose visitor is a toplevel function allocates nothing. *)
let walk_with bvh (stack : float array) ox oy oz dx dy dz (lim : float array) visit a b c e =
  (* the stack holds (node, entry distance) pairs; a node whose box starts beyond the current
     limit when it is popped is skipped *)
  if bvh.nodes > 0 then begin
    let idx = recip dx and idy = recip dy and idz = recip dz in
    let sp = ref 0 in
    let t0 = entry bvh 0 ox oy oz idx idy idz 0. lim.(0) in
    if t0 < infinity then begin stack.(0) <- 0.; stack.(1) <- t0; sp := 1 end;
    while !sp > 0 do
      decr sp;
      if stack.((2 * !sp) + 1) <= lim.(0) then begin
        let k = int_of_float stack.(2 * !sp) in
        let l = bvh.links in
        let axis = iget l ((3 * k) + 2) in
        if axis < 0 then begin
          let first = iget l (3 * k) and cnt = iget l ((3 * k) + 1) in
          for j = first to first + cnt - 1 do
            visit a b c e (iget bvh.order j)
          done
        end
        else begin
          let a = iget l (3 * k) and b = iget l ((3 * k) + 1) in
          let limit = lim.(0) in
          let ta = entry bvh a ox oy oz idx idy idz 0. limit and tb = entry bvh b ox oy oz idx idy idz 0. limit in
          (* push the farther child first so that the nearer one is visited first *)
          let a_first = ta <= tb in
          let tf = if a_first then tb else ta and tn = if a_first then ta else tb in
          if tf < infinity then begin
            stack.(2 * !sp) <- float_of_int (if a_first then b else a);
            stack.((2 * !sp) + 1) <- tf;
            incr sp
          end;
          if tn < infinity then begin
            stack.(2 * !sp) <- float_of_int (if a_first then a else b);
            stack.((2 * !sp) + 1) <- tn;
            incr sp
          end
        end
      end
    done
  end

(* [walk] with the limit in a one-slot array, lowered to what [visit] returns. *)
let walk bvh stack ox oy oz dx dy dz limit0 visit =
  let lim = [| limit0 |] in
  walk_with bvh stack ox oy oz dx dy dz lim (fun visit () () () i -> lim.(0) <- fmin lim.(0) (visit i)) visit () () ()

let box_min t a = fget t.boxes a
let box_max t a = fget t.boxes (3 + a)

(* The same tree with its primitives renumbered in leaf order (so that primitives met together lie
   together in memory): new primitive j is old primitive perm.(j). *)
let renumber t =
  let n = Array1.dim t.order in
  let perm = Array.init n (fun j -> iget t.order j) in
  let order = Array1.create int32 c_layout n in
  for j = 0 to n - 1 do iset order j j done;
  ({ t with order }, perm)
