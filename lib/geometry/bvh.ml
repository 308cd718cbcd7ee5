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

let f32 x = Int32.float_of_bits (Int32.bits_of_float x)

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

let empty = { boxes = create_boxes 0; links = Array1.create int32 c_layout 0; order = Array1.create int32 c_layout 0; nodes = 0 }

(* Surface area (half of it; only ratios matter) of a box given as six floats. *)
let half_area x0 y0 z0 x1 y1 z1 =
  let dx = x1 -. x0 and dy = y1 -. y0 and dz = z1 -. z0 in
  if dx < 0. then 0. else (dx *. dy) +. (dy *. dz) +. (dz *. dx)

let build (prim : f32s) =
  (* [prim] holds 6 values per primitive: its box, as [set_box] stores it *)
  let n = Array1.dim prim / 6 in
  if n = 0 then empty
  else begin
    let order = Array1.create int32 c_layout n in
    for i = 0 to n - 1 do iset order i i done;
    let[@inline] centre i a = 0.5 *. (fget prim ((6 * i) + a) +. fget prim ((6 * i) + 3 + a)) in
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
    let bin_box = Array.make (6 * bins) 0. and bin_n = Array.make bins 0 in
    let right_area = Array.make bins 0. and right_n = Array.make bins 0 in
    let rec node first cnt =
      let id = !count in
      incr count;
      reserve id;
      let boxes = !boxes_r and links = !links_r in
      (* bounds of the primitives and of their centres *)
      let bx0 = ref infinity and by0 = ref infinity and bz0 = ref infinity in
      let bx1 = ref neg_infinity and by1 = ref neg_infinity and bz1 = ref neg_infinity in
      let cx0 = ref infinity and cy0 = ref infinity and cz0 = ref infinity in
      let cx1 = ref neg_infinity and cy1 = ref neg_infinity and cz1 = ref neg_infinity in
      for k = first to first + cnt - 1 do
        let o = 6 * iget order k in
        let x0 = fget prim o and y0 = fget prim (o + 1) and z0 = fget prim (o + 2) in
        let x1 = fget prim (o + 3) and y1 = fget prim (o + 4) and z1 = fget prim (o + 5) in
        bx0 := fmin !bx0 x0; by0 := fmin !by0 y0; bz0 := fmin !bz0 z0;
        bx1 := fmax !bx1 x1; by1 := fmax !by1 y1; bz1 := fmax !bz1 z1;
        let cx = 0.5 *. (x0 +. x1) and cy = 0.5 *. (y0 +. y1) and cz = 0.5 *. (z0 +. z1) in
        cx0 := fmin !cx0 cx; cy0 := fmin !cy0 cy; cz0 := fmin !cz0 cz;
        cx1 := fmax !cx1 cx; cy1 := fmax !cy1 cy; cz1 := fmax !cz1 cz
      done;
      let b = [| !bx0; !by0; !bz0; !bx1; !by1; !bz1 |] in
      let c = [| !cx0; !cy0; !cz0; !cx1; !cy1; !cz1 |] in
      for q = 0 to 5 do Array1.unsafe_set boxes ((6 * id) + q) b.(q) done;
      let leaf () = iset links (3 * id) first; iset links ((3 * id) + 1) cnt; iset links ((3 * id) + 2) (-1) in
      let ext a = c.(3 + a) -. c.(a) in
      let widest = if ext 0 >= ext 1 && ext 0 >= ext 2 then 0 else if ext 1 >= ext 2 then 1 else 2 in
      (* Large nodes are split at the middle of their centres along the widest axis: far cheaper
         than binning, and for big meshes nearly as good; the SAH decides below that size. *)
      let mid_split () =
        let a = widest in
        let m = 0.5 *. (c.(a) +. c.(3 + a)) in
        let i = ref first and j = ref (first + cnt - 1) in
        while !i <= !j do
          if centre (iget order !i) a < m then incr i
          else begin
            let t = iget order !i in
            iset order !i (iget order !j); iset order !j t; decr j
          end
        done;
        !i - first
      in
      let nl = if cnt > 8192 && ext widest > 0. then mid_split () else 0 in
      if nl > 0 && nl < cnt then begin
        iset links ((3 * id) + 2) widest;
        let l = node first nl in
        let r = node (first + nl) (cnt - nl) in
        iset !links_r (3 * id) l; iset !links_r ((3 * id) + 1) r
      end
      else if cnt <= leaf_size then leaf ()
      else begin
        (* binned SAH *)
        let best_cost = ref infinity and best_axis = ref (-1) and best_split = ref 0 in
        (* bin along the axis where the centres spread most *)
        for a = widest to widest do
          let lo = c.(a) and hi = c.(3 + a) in
          if hi > lo then begin
            let scale = float_of_int bins /. (hi -. lo) in
            for j = 0 to bins - 1 do
              bin_n.(j) <- 0;
              for q = 0 to 2 do bin_box.((6 * j) + q) <- infinity; bin_box.((6 * j) + 3 + q) <- neg_infinity done
            done;
            for k = first to first + cnt - 1 do
              let i = iget order k in
              let j = imin (bins - 1) (int_of_float ((centre i a -. lo) *. scale)) in
              bin_n.(j) <- bin_n.(j) + 1;
              for q = 0 to 2 do
                bin_box.((6 * j) + q) <- fmin bin_box.((6 * j) + q) (fget prim ((6 * i) + q));
                bin_box.((6 * j) + 3 + q) <- fmax bin_box.((6 * j) + 3 + q) (fget prim ((6 * i) + 3 + q))
              done
            done;
            (* sweep from the right, then from the left *)
            let acc = Array.make 6 0. in
            let reset () = acc.(0) <- infinity; acc.(1) <- infinity; acc.(2) <- infinity; acc.(3) <- neg_infinity; acc.(4) <- neg_infinity; acc.(5) <- neg_infinity in
            let grow j = for q = 0 to 2 do acc.(q) <- fmin acc.(q) bin_box.((6 * j) + q); acc.(3 + q) <- fmax acc.(3 + q) bin_box.((6 * j) + 3 + q) done in
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
                if cost < !best_cost then begin best_cost := cost; best_axis := a; best_split := j + 1 end
              end
            done
          end
        done;
        let parent_cost = half_area b.(0) b.(1) b.(2) b.(3) b.(4) b.(5) *. float_of_int cnt in
        if !best_axis < 0 || (!best_cost >= parent_cost && cnt <= 8) then
          if !best_axis < 0 && cnt > leaf_size then begin
            (* all centres coincide: split in the middle of the list *)
            let half = cnt / 2 in
            iset links ((3 * id) + 2) 0;
            let l = node first half in
            let r = node (first + half) (cnt - half) in
            iset !links_r (3 * id) l; iset !links_r ((3 * id) + 1) r
          end
          else leaf ()
        else begin
          let a = !best_axis in
          let lo = c.(a) and hi = c.(3 + a) in
          let scale = float_of_int bins /. (hi -. lo) in
          let bin_of i = imin (bins - 1) (int_of_float ((centre i a -. lo) *. scale)) in
          (* partition order[first..first+cnt) by bin < best_split *)
          let i = ref first and j = ref (first + cnt - 1) in
          while !i <= !j do
            if bin_of (iget order !i) < !best_split then incr i
            else begin
              let t = iget order !i in
              iset order !i (iget order !j); iset order !j t; decr j
            end
          done;
          let nl = !i - first in
          iset links ((3 * id) + 2) a;
          let l = node first nl in
          let r = node (first + nl) (cnt - nl) in
          iset !links_r (3 * id) l; iset !links_r ((3 * id) + 1) r
        end
      end;
      id
    in
    ignore (node 0 n);
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

(* Visit the primitives whose boxes the ray meets, nearer boxes first; [visit i] returns the new
   limit beyond which boxes are skipped. *)
let walk bvh (stack : float array) ox oy oz dx dy dz limit0 visit =
  (* the stack holds (node, entry distance) pairs; a node whose box starts beyond the current
     limit when it is popped is skipped *)
  if bvh.nodes > 0 then begin
    let idx = recip dx and idy = recip dy and idz = recip dz in
    let limit = ref limit0 in
    let sp = ref 0 in
    let t0 = entry bvh 0 ox oy oz idx idy idz 0. !limit in
    if t0 < infinity then begin stack.(0) <- 0.; stack.(1) <- t0; sp := 1 end;
    while !sp > 0 do
      decr sp;
      if stack.((2 * !sp) + 1) <= !limit then begin
        let k = int_of_float stack.(2 * !sp) in
        let l = bvh.links in
        let axis = iget l ((3 * k) + 2) in
        if axis < 0 then begin
          let first = iget l (3 * k) and cnt = iget l ((3 * k) + 1) in
          for j = first to first + cnt - 1 do
            limit := fmin !limit (visit (iget bvh.order j))
          done
        end
        else begin
          let a = iget l (3 * k) and b = iget l ((3 * k) + 1) in
          let ta = entry bvh a ox oy oz idx idy idz 0. !limit and tb = entry bvh b ox oy oz idx idy idz 0. !limit in
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
