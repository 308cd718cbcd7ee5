(* The nearest-hit search and POV-Ray's tie rules (§2.1). *)

open Compiled
open Context

let tie_tolerance (o : Vec.t) t = 0x1p-36 *. (Float.max (Float.abs o.x) (Float.max (Float.abs o.y) (Float.abs o.z)) +. t)

(* Depths this close to each other (relative) are equal but for rounding: POV-Ray's search may find
   either, according to the order in which it meets the objects' boxes. *)
let near_tie = 1e-9

(* How far beyond the best depth [best] found the walk still meets boxes: by the tie width, so
   that an object hit just beyond the best is seen to tie. *)
let[@inline] beyond ctx (o : Vec.t) best = if ctx.robust then best +. tie_tolerance o best else best +. (near_tie *. Float.abs best)

(* Whether POV-Ray's search meets [ob] at all: only if the ray crosses its single-precision box
   (as its tree's Check_And_Enqueue, or without the tree Intersect_BBox, tests it), which a ray
   grazing the box's edge may miss by rounding while it meets the shape (a box's own edge) *)
let crosses_box ctx (ob : obj) (o : Vec.t) (d : Vec.t) =
  Array.length ob.pbox = 0
  || if ctx.scene.bounding then Pov_box.entry ob.pbox o d < infinity else Pov_box.met ob.pbox o d ~within:infinity

(* Whether [ob], hit at depth [t], replaces the current best [cur] at depth [best]. Nearer
   replaces, if POV-Ray's search meets the object; a hit of another top-level object within
   rounding of the best is noted, and the ray is then searched again as POV-Ray searches it
   ([search]). In the robust mode, of depths within the tie width the one written first. *)
let[@inline] replaces ctx (ob : obj) t best cur (o : Vec.t) (d : Vec.t) =
  if not ctx.robust then begin
    if cur >= 0 && Float.abs (t -. best) <= near_tie *. Float.abs best && ctx.scene.objects.(cur).top <> ob.id then
      ctx.found.near <- true;
    t < best && crosses_box ctx ob o d
  end
  else if cur < 0 then t < best
  else
    let tol = tie_tolerance o best in
    t < best -. tol || (t <= best +. tol && ob.id < cur)

(* the slab test's min and max (as the hierarchy's: no −0 or NaN ordering, no C call) *)
let[@inline] fmin (a : float) b = if a < b then a else b
let[@inline] fmax (a : float) b = if a > b then a else b
let[@inline] recip x = if x = 0. then 1e300 else 1. /. x

(* what the shape just tested reported of the crossing it found, kept with the new best *)
let[@inline] keep_report ctx =
  let w = ctx.shapes in
  ctx.found.reported <- w.reported;
  if w.reported then Crossing.blit w.crossing ctx.crossing

(* the test of the object [ob], the best so far in [ctx.found] and [ctx.reach] *)
let try_obj ctx (ob : obj) (o : Vec.t) (d : Vec.t) =
  let f = ctx.found and r = ctx.reach in
  ctx.shapes.reported <- false;
  let t = Shape.depth ctx.shapes ob.shape o d r.least in
  if replaces ctx ob t r.depth f.id o d then begin
    r.depth <- t;
    f.id <- Shape.hit_object ctx.shapes ob;
    f.part <- ctx.shapes.part;
    keep_report ctx
  end

(* the visitor of the bounded object [i] of [g] met by the walk of the ray from [o] along [d] (a
   toplevel function, its values passed through the walk: a search builds no closure or record) *)
let visit_bounded ctx (g : group) (o : Vec.t) (d : Vec.t) i =
  let f = ctx.found and r = ctx.reach in
  let sp = g.spheres and bx = g.boxes in
  let r2 = Array.unsafe_get sp ((4 * i) + 3) in
  if r2 = r2 then begin
    (* a sphere, straight from the flat array *)
    let t = Sphere.depth_at ctx.stats ctx.shapes.lim (Array.unsafe_get sp (4 * i)) (Array.unsafe_get sp ((4 * i) + 1)) (Array.unsafe_get sp ((4 * i) + 2)) r2 o d r.least in
    if replaces ctx (Array.unsafe_get g.bounded i) t r.depth f.id o d then begin
      r.depth <- t;
      f.id <- (Array.unsafe_get g.bounded i).id;
      f.part <- -1;
      f.reported <- false
    end
  end
  else begin
    let b = 6 * i in
    let x0 = Array.unsafe_get bx b in
    if x0 <> x0 then try_obj ctx g.bounded.(i) o d
    else begin
      (* a costly shape is tried only when the ray meets its own box before the limit, as
         it would meet the box of a leaf holding the shape alone *)
      let best = r.depth in
      let lim = if f.id >= 0 then beyond ctx o best else best in
      let idx = r.inv_dx and idy = r.inv_dy and idz = r.inv_dz in
      let tx0 = (x0 -. o.x) *. idx and tx1 = (Array.unsafe_get bx (b + 3) -. o.x) *. idx in
      let ty0 = (Array.unsafe_get bx (b + 1) -. o.y) *. idy and ty1 = (Array.unsafe_get bx (b + 4) -. o.y) *. idy in
      let tz0 = (Array.unsafe_get bx (b + 2) -. o.z) *. idz and tz1 = (Array.unsafe_get bx (b + 5) -. o.z) *. idz in
      let near = fmax (fmax (fmin tx0 tx1) (fmin ty0 ty1)) (fmax (fmin tz0 tz1) 0.) in
      let far = fmin (fmin (fmax tx0 tx1) (fmax ty0 ty1)) (fmin (fmax tz0 tz1) lim) in
      if near <= far then try_obj ctx g.bounded.(i) o d
    end
  end;
  (* ties may lie just beyond the best depth *)
  let l = if f.id >= 0 then beyond ctx o r.depth else r.depth in
  let wl = ctx.walk_limit in
  wl.(0) <- fmin wl.(0) l

(* POV-Ray's search: each object the walk of its tree pops, nearest box first
   (Intersect_BBox_Tree), or without the tree every object in scene order whose box the ray
   crosses (FindIntersection); an object is kept when strictly nearer than the best so far *)
let pov_search ctx (ord : order) (o : Vec.t) (d : Vec.t) =
  let f = ctx.found and r = ctx.reach in
  let test (ob : obj) =
    ctx.shapes.reported <- false;
    let t = Shape.depth ctx.shapes ob.shape o d r.least in
    if t < r.depth then begin
      r.depth <- t;
      f.id <- Shape.hit_object ctx.shapes ob;
      f.part <- ctx.shapes.part;
      keep_report ctx
    end
  in
  match ord with
  | Tree { tree; member } -> Slab_tree.search tree ctx.pov_room o d (fun () -> r.depth) (fun id -> if member.(id) then test ctx.scene.objects.(id))
  | Listed obs -> Array.iter (fun (ob : obj) -> if Pov_box.met ob.pbox o d ~within:infinity then test ob) obs

(* povml's search: the unbounded objects one by one, then its own hierarchy *)
let bvh_search ctx (g : group) (o : Vec.t) (d : Vec.t) hi =
  let r = ctx.reach in
  let un = g.unbounded in
  for k = 0 to Array.length un - 1 do try_obj ctx (Array.unsafe_get un k) o d done;
  r.inv_dx <- recip d.x;
  r.inv_dy <- recip d.y;
  r.inv_dz <- recip d.z;
  if g.bvh.nodes > 0 then begin
    ctx.walk_limit.(0) <- hi;
    Bvh.walk_with g.bvh ctx.stack o.x o.y o.z d.x d.y d.z ctx.walk_limit visit_bounded ctx g o d
  end

(* the kind of ray the shapes are asked about: an isosurface keeps no cache for a shadow ray *)
let[@inline] asked ctx (kind : Ray.kind) =
  ctx.shapes.shadow_ray <- (match kind with Shadow -> true | Camera | Reflected | Transmitted | Continued -> false)

type found = Context.t

let search ctx (kind : Ray.kind) (g : group) (o : Vec.t) (d : Vec.t) lo hi : found =
  let f = ctx.found and r = ctx.reach in
  asked ctx kind;
  r.depth <- hi;
  f.id <- -1;
  f.part <- -1;
  f.reported <- false;
  r.least <- lo;
  f.near <- false;
  if ctx.robust then bvh_search ctx g o d hi
  else if g.pov_always then pov_search ctx (Lazy.force g.pov) o d
  else begin
    bvh_search ctx g o d hi;
    (* a near tie: which object POV-Ray finds depends on its order of search *)
    if f.near then begin
      r.depth <- hi;
      f.id <- -1;
      f.part <- -1;
      f.reported <- false;
      pov_search ctx (Lazy.force g.pov) o d
    end
  end;
  ctx

(* what the worker's last search found *)
let[@inline] hit (w : found) = w.found.id >= 0
let[@inline] id (w : found) = w.found.id
let[@inline] part (w : found) = w.found.part
let[@inline] depth (w : found) = w.reach.depth
let crossing (w : found) = if w.found.reported then Crossing.copy w.crossing else Crossing.none

let shape_depth ctx (kind : Ray.kind) shape o d lo =
  asked ctx kind;
  Shape.depth ctx.shapes shape o d lo

let cached_depth ctx (kind : Ray.kind) shape o d lo hi =
  asked ctx kind;
  Shape.cached_depth ctx.shapes shape o d lo hi
