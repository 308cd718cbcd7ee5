(* The blob (shape/blob.cpp, bounding/bsphere.cpp): a field of spherical and cylindrical
   components whose sum equals the threshold on the surface. *)

type kind = Sphere | Ellipsoid | Base_hemisphere | Apex_hemisphere | Cylinder

type component = {
  kind : kind;
  origin : Vec.t;
  len : float;
  rad2 : float;
  strength : float;
  ctrans : Transform.t option;
  tex : int;
}

type t = {
  components : component list;
  threshold : float;
  sturm : bool;
  hierarchy : bool;
  trans : Transform.t option;
  box : float array option;
}

let epsilon = Precision.epsilon
let bound_huge = 2e10
let max_distance = 1e7
let depth_tolerance = 1e-2 (* DEPTH_TOLERANCE of blob.cpp *)
let inside_tolerance = 1e-6 (* INSIDE_TOLERANCE *)
let small_tolerance = 1e-3 (* SMALL_TOLERANCE of frame.h *)
let root_epsilon = 1e-11 (* the root elimination ratio All_Intersections passes the solver *)

(* ---------------------------------------------------------------------------------------------- *)
(* Components as the parser makes and moves them (Parse_Blob, the *_Blob_Element functions). *)

let sphere_component ~centre ~radius ~strength =
  { kind = Sphere; origin = centre; len = 0.; rad2 = radius *. radius; strength; ctrans = None; tex = -1 }

let cylinder_component ~base ~apex ~radius ~strength =
  let axis = Vec.sub apex base in
  let len = sqrt ((axis.x *. axis.x) +. (axis.y *. axis.y) +. (axis.z *. axis.z)) in
  if len < epsilon then None
  else
    let k = 1. /. len in
    let axis = Vec.make (axis.x *. k) (axis.y *. k) (axis.z *. k) in
    let tr, _ = Transform.coordinate base axis 1. 1. in
    Some { kind = Cylinder; origin = Vec.zero; len; rad2 = radius *. radius; strength; ctrans = Some tr; tex = -1 }

(* Transform_Blob_Element: a sphere becomes an ellipsoid with a transform of its own *)
let transform_component c tr =
  match c.ctrans with
  | None -> { c with kind = Ellipsoid; ctrans = Some (Transform.compose Transform.identity tr) }
  | Some t -> { c with ctrans = Some (Transform.compose t tr) }

let translate_component c v =
  match c.ctrans with None -> { c with origin = Vec.add c.origin v } | Some _ -> transform_component c (Transform.translate v)

let rotate_component c v =
  let tr = Transform.rotate v in
  match c.ctrans with None -> { c with origin = Transform.point tr c.origin } | Some _ -> transform_component c tr

let scale_component c (v : Vec.t) =
  let c = if (v.x <> v.y || v.x <> v.z) && c.ctrans = None then { c with kind = Ellipsoid; ctrans = Some Transform.identity } else c in
  match c.ctrans with
  | None -> { c with origin = Vec.scale v.x c.origin; rad2 = c.rad2 *. (v.x *. v.x) }
  | Some t -> { c with ctrans = Some (Transform.compose t (Transform.scale v)) }

let with_texture c tex = { c with tex }

(* ---------------------------------------------------------------------------------------------- *)
(* The elements Make_Blob sets up: a cylinder is followed by its base and apex hemispheres. *)

type element = {
  ekind : kind;
  index : int;
  ox : float;
  oy : float;
  oz : float;
  elen : float;
  erad2 : float;
  c0 : float;
  c1 : float;
  c2 : float;
  etr : Transform.t;  (** identity for a sphere, which has none *)
  etex : int;
}

let elements_of (b : t) =
  let one c kind index =
    let rad2 = c.rad2 and coeff = c.strength in
    {
      ekind = kind;
      index;
      ox = c.origin.x;
      oy = c.origin.y;
      oz = c.origin.z;
      elen = c.len;
      erad2 = rad2;
      c0 = coeff /. (rad2 *. rad2);
      c1 = -.(2.0 *. coeff) /. rad2;
      c2 = coeff;
      etr = (match c.ctrans with Some t -> t | None -> Transform.identity);
      etex = c.tex;
    }
  in
  let rec go i = function
    | [] -> []
    | c :: rest -> (
        match c.kind with
        | Cylinder -> one c Cylinder i :: one c Base_hemisphere (i + 1) :: one c Apex_hemisphere (i + 2) :: go (i + 3) rest
        | Sphere | Ellipsoid | Base_hemisphere | Apex_hemisphere -> one c c.kind i :: go (i + 1) rest)
  in
  Array.of_list (go 0 b.components)

let has_trans e = match e.ekind with Sphere -> false | Ellipsoid | Base_hemisphere | Apex_hemisphere | Cylinder -> true

(* get_element_bounding_sphere: a transformed element's sphere has the radius of the largest side
   of the box of the cube [0, r]³ mapped by its transform (single precision), squared, plus
   EPSILON *)
let bounding_sphere e =
  let c, r2 =
    match e.ekind with
    | Sphere | Ellipsoid -> (Vec.make e.ox e.oy e.oz, e.erad2)
    | Base_hemisphere -> (Vec.zero, e.erad2)
    | Apex_hemisphere -> (Vec.make 0. 0. e.elen, e.erad2)
    | Cylinder ->
        let h = 0.5 *. e.elen in
        (Vec.make 0. 0. (0.5 *. e.elen), e.erad2 +. (h *. h))
  in
  if not (has_trans e) then (c, r2)
  else
    let r = sqrt r2 in
    let c = Transform.point e.etr c in
    let b = Pov_box.mapped e.etr (Pov_box.of_min_max [| 0.; 0.; 0. |] [| r; r; r |]) in
    let r = Float.max (Float.max (Float.abs b.(3)) (Float.abs b.(4))) (Float.abs b.(5)) in
    (c, (r *. r) +. epsilon)

let blob_space_box elems =
  let lo = [| bound_huge; bound_huge; bound_huge |] and hi = [| -.bound_huge; -.bound_huge; -.bound_huge |] in
  Array.iter
    (fun e ->
      if e.c2 > 0. then begin
        let (c : Vec.t), r2 = bounding_sphere e in
        let r = sqrt r2 in
        lo.(0) <- Float.min lo.(0) (c.x -. r);
        lo.(1) <- Float.min lo.(1) (c.y -. r);
        lo.(2) <- Float.min lo.(2) (c.z -. r);
        hi.(0) <- Float.max hi.(0) (c.x +. r);
        hi.(1) <- Float.max hi.(1) (c.y +. r);
        hi.(2) <- Float.max hi.(2) (c.z +. r)
      end)
    elems;
  (lo, hi)

(* Compute_BBox *)
let compute_box b =
  let lo, hi = blob_space_box (elements_of b) in
  let box = Pov_box.of_min_max lo hi in
  match b.trans with None -> box | Some tr -> Pov_box.mapped tr box

let finish b = { b with box = Some (compute_box b) }

(* Blob::Transform: composed into Trans; a box already set up is mapped (Recompute_BBox) *)
let transform b tr =
  let trans = Some (match b.trans with None -> Transform.compose Transform.identity tr | Some t -> Transform.compose t tr) in
  { b with trans; box = Option.map (Pov_box.mapped tr) b.box }

(* ---------------------------------------------------------------------------------------------- *)
(* The bounding sphere hierarchy (Build_Bounding_Sphere_Hierarchy, bsphere.cpp), flattened. *)

type tree = {
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

let no_tree = { cx = [||]; cy = [||]; cz = [||]; r2 = [||]; entries = [||]; first = [||]; kids = [||]; root = -1 }

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

(* ---------------------------------------------------------------------------------------------- *)
(* The compiled blob. *)

type compiled = {
  elems : element array;
  thresh : float;
  csturm : bool;
  ctr : Transform.t option;
  tree : tree;
  cbox : float array;
  exact : float array;  (** the box in doubles: blob-space extent mapped by the transform *)
  textured : bool;  (** some component has a texture of its own (MULTITEXTURE_FLAG) *)
}

let compile (b : t) =
  let elems = elements_of b in
  let tree =
    if not b.hierarchy then no_tree
    else
      let leaves =
        Array.to_list
          (Array.mapi
             (fun i e ->
               let c, r2 = bounding_sphere e in
               { bc = c; br2 = r2; bkids = [||]; belem = i })
             elems)
      in
      match build_hierarchy leaves with None -> no_tree | Some root -> flatten root
  in
  let lo, hi = blob_space_box elems in
  let raw = Array.append lo hi in
  let exact = match b.trans with None -> raw | Some tr -> Transform.bounds tr raw in
  {
    elems;
    thresh = b.threshold;
    csturm = b.sturm;
    ctr = b.trans;
    tree;
    cbox = (match b.box with Some box -> box | None -> compute_box b);
    exact;
    textured = Array.exists (fun e -> e.etex >= 0) elems;
  }

let node_count c = Array.length c.tree.entries

(* the room of one intersection, grown to this blob's size *)
let room (w : Scratch.t) c =
  let r = w.blob and n = Array.length c.elems in
  if Array.length r.bounds < (2 * n) + 2 then begin
    r.bounds <- Array.make ((2 * n) + 2) 0.;
    r.marks <- Array.make ((2 * n) + 2) 0
  end;
  if Array.length r.fcoeffs < 5 * n then r.fcoeffs <- Array.make (5 * n) 0.;
  if Array.length r.queue < node_count c + 1 then r.queue <- Array.make (node_count c + 1) 0;
  r

(* ---------------------------------------------------------------------------------------------- *)
(* Where each element is active along the ray (intersect_element and its cases): the entry and
   exit depths left in [acc.(5)] and [acc.(6)]. *)

let set_span (r : Scratch.blob_room) tmin tmax =
  r.acc.(5) <- tmin;
  r.acc.(6) <- tmax

let sphere_span r e px py pz dx dy dz mindist =
  let vx = px -. e.ox and vy = py -. e.oy and vz = pz -. e.oz in
  let b = (vx *. dx) +. (vy *. dy) +. (vz *. dz) in
  let t = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
  let d = (b *. b) -. t +. e.erad2 in
  if d < epsilon then false
  else
    let d = sqrt d in
    let tmax = -.b +. d in
    let tmax = if tmax < mindist then 0. else tmax in
    let tmin = -.b -. d in
    let tmin = if tmin < mindist then 0. else tmin in
    if tmax = tmin then false
    else begin
      if tmax < tmin then set_span r tmax tmin else set_span r tmin tmax;
      true
    end

(* the ray in an element's space, its direction unit: [acc.(0 … 6)] are free until the spans are
   found, so the moved ray is returned as floats through a small record-free path *)
let[@inline] in_element e px py pz dx dy dz k =
  let m = e.etr in
  match k with
  | 0 -> (px *. m.i00) +. (py *. m.i10) +. (pz *. m.i20) +. m.i30
  | 1 -> (px *. m.i01) +. (py *. m.i11) +. (pz *. m.i21) +. m.i31
  | 2 -> (px *. m.i02) +. (py *. m.i12) +. (pz *. m.i22) +. m.i32
  | 3 -> (dx *. m.i00) +. (dy *. m.i10) +. (dz *. m.i20)
  | 4 -> (dx *. m.i01) +. (dy *. m.i11) +. (dz *. m.i21)
  | _ -> (dx *. m.i02) +. (dy *. m.i12) +. (dz *. m.i22)

let ellipsoid_span r e px py pz dx dy dz mindist =
  let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 and qz = in_element e px py pz dx dy dz 2 in
  let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
  let len = sqrt ((ux *. ux) +. (uy *. uy) +. (uz *. uz)) in
  let k = 1. /. len in
  let ux = ux *. k and uy = uy *. k and uz = uz *. k in
  let vx = qx -. e.ox and vy = qy -. e.oy and vz = qz -. e.oz in
  let b = (vx *. ux) +. (vy *. uy) +. (vz *. uz) in
  let t = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
  let d = (b *. b) -. t +. e.erad2 in
  if d < epsilon then false
  else
    let d = sqrt d in
    let tmax = (-.b +. d) /. len in
    let tmax = if tmax < mindist then 0. else tmax in
    let tmin = (-.b -. d) /. len in
    let tmin = if tmin < mindist then 0. else tmin in
    if tmax = tmin then false
    else begin
      if tmax < tmin then set_span r tmax tmin else set_span r tmin tmax;
      true
    end

(* intersect_hemisphere: the sphere's span cut by the plane z = 0 (base: the half z ≤ 0) or
   z = len (apex: the half above) *)
let hemisphere_span r e px py pz dx dy dz mindist =
  let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 and qz = in_element e px py pz dx dy dz 2 in
  let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
  let len = sqrt ((ux *. ux) +. (uy *. uy) +. (uz *. uz)) in
  let k = 1. /. len in
  let ux = ux *. k and uy = uy *. k and uz = uz *. k in
  let base = match e.ekind with Base_hemisphere -> true | Sphere | Ellipsoid | Apex_hemisphere | Cylinder -> false in
  let qz = if base then qz else qz -. e.elen in
  let b = (qx *. ux) +. (qy *. uy) +. (qz *. uz) in
  let t = (qx *. qx) +. (qy *. qy) +. (qz *. qz) in
  let d = (b *. b) -. t +. e.erad2 in
  if d < epsilon then false
  else
    let d = sqrt d in
    let tmax = -.b +. d and tmin = -.b -. d in
    let tmin, tmax = if tmax < tmin then (tmax, tmin) else (tmin, tmax) in
    let z1 = qz +. (tmin *. uz) and z2 = qz +. (tmax *. uz) in
    (* which side of the plane is the element's: z ≤ 0 for the base, z > 0 for the apex *)
    let inside1 = if base then z1 >= 0.0 else z1 <= 0.0 and inside2 = if base then z2 >= 0.0 else z2 <= 0.0 in
    if inside1 && inside2 then false
    else if (not inside1) && not inside2 then begin
      set_span r (tmin /. len) (tmax /. len);
      true
    end
    else
      let t = -.qz /. uz in
      let tmin, tmax = if inside1 then ((if t < mindist then 0.0 else t), tmax) else (tmin, if t < mindist then 0.0 else t) in
      set_span r (tmin /. len) (tmax /. len);
      true

let cylinder_span r e px py pz dx dy dz mindist =
  let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 and qz = in_element e px py pz dx dy dz 2 in
  let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
  let len = sqrt ((ux *. ux) +. (uy *. uy) +. (uz *. uz)) in
  let k = 1. /. len in
  let ux = ux *. k and uy = uy *. k and uz = uz *. k in
  let tmin = ref bound_huge and tmax = ref (-.bound_huge) in
  let keep t =
    if t < !tmin then tmin := t;
    if t > !tmax then tmax := t
  in
  let a = (ux *. ux) +. (uy *. uy) in
  if a > epsilon then begin
    let b = (qx *. ux) +. (qy *. uy) in
    let c = (qx *. qx) +. (qy *. qy) -. e.erad2 in
    let d = (b *. b) -. (a *. c) in
    if d > epsilon then begin
      let d = sqrt d in
      let t = (-.b +. d) /. a in
      let h = qz +. (t *. uz) in
      if h >= 0.0 && h <= e.elen then keep t;
      let t = (-.b -. d) /. a in
      let h = qz +. (t *. uz) in
      if h >= 0.0 && h <= e.elen then keep t
    end
  end;
  if Float.abs uz > epsilon then begin
    let t = -.qz /. uz in
    let u = qx +. (t *. ux) and v = qy +. (t *. uy) in
    if (u *. u) +. (v *. v) <= e.erad2 then keep t;
    let t = (e.elen -. qz) /. uz in
    let u = qx +. (t *. ux) and v = qy +. (t *. uy) in
    if (u *. u) +. (v *. v) <= e.erad2 then keep t
  end;
  let tmin = !tmin /. len and tmax = !tmax /. len in
  let tmin = if tmin < mindist then 0.0 else tmin and tmax = if tmax < mindist then 0.0 else tmax in
  if tmin >= tmax then false
  else begin
    set_span r tmin tmax;
    true
  end

let element_span (w : Scratch.t) r e px py pz dx dy dz mindist =
  let s = w.stats in
  s.blob_element_tests <- s.blob_element_tests + 1;
  let hit =
    match e.ekind with
    | Sphere -> sphere_span r e px py pz dx dy dz mindist
    | Ellipsoid -> ellipsoid_span r e px py pz dx dy dz mindist
    | Base_hemisphere | Apex_hemisphere -> hemisphere_span r e px py pz dx dy dz mindist
    | Cylinder -> cylinder_span r e px py pz dx dy dz mindist
  in
  if hit then s.blob_element_hits <- s.blob_element_hits + 1;
  hit

(* insert_hit: the entry and exit of element [idx] put in the sorted list of [cnt] entries *)
let insert_hit (r : Scratch.blob_room) idx t0 t1 cnt =
  let bd = r.bounds and mk = r.marks in
  bd.(cnt) <- t0;
  mk.(cnt) <- 2 * idx;
  let k = ref 0 in
  while t0 > bd.(!k) do
    incr k
  done;
  if !k < cnt then begin
    let k0 = !k in
    Array.blit bd k0 bd (k0 + 1) (cnt - k0);
    Array.blit mk k0 mk (k0 + 1) (cnt - k0);
    bd.(k0) <- t0;
    mk.(k0) <- 2 * idx;
    let cnt = cnt + 1 in
    bd.(cnt) <- t1;
    mk.(cnt) <- (2 * idx) + 1;
    let k = ref (k0 + 1) in
    while t1 > bd.(!k) do
      incr k
    done;
    if !k < cnt then begin
      let k1 = !k in
      Array.blit bd k1 bd (k1 + 1) (cnt - k1);
      Array.blit mk k1 mk (k1 + 1) (cnt - k1);
      bd.(k1) <- t1;
      mk.(k1) <- (2 * idx) + 1
    end;
    cnt + 1
  end
  else begin
    bd.(cnt + 1) <- t1;
    mk.(cnt + 1) <- (2 * idx) + 1;
    cnt + 2
  end

(* determine_influences: every element, or those the hierarchy reaches (its nodes taken from the
   top of a stack, the children of a node pushed in order when the ray passes within its sphere) *)
let influences (w : Scratch.t) r c px py pz dx dy dz mindist =
  let cnt = ref 0 in
  let tr = c.tree in
  if tr.root < 0 then
    Array.iteri
      (fun i e -> if element_span w r e px py pz dx dy dz mindist then cnt := insert_hit r i r.acc.(5) r.acc.(6) !cnt)
      c.elems
  else begin
    let q = r.queue and s = w.stats in
    q.(0) <- tr.root;
    let size = ref 1 in
    while !size > 0 do
      decr size;
      let nd = q.(!size) in
      let ne = tr.entries.(nd) in
      if ne <= 0 then begin
        let i = tr.first.(nd) in
        if element_span w r c.elems.(i) px py pz dx dy dz mindist then cnt := insert_hit r i r.acc.(5) r.acc.(6) !cnt
      end
      else
        for j = 0 to ne - 1 do
          let ch = tr.kids.(tr.first.(nd) + j) in
          s.blob_bound_tests <- s.blob_bound_tests + 1;
          let vx = tr.cx.(ch) -. px and vy = tr.cy.(ch) -. py and vz = tr.cz.(ch) -. pz in
          let b = (vx *. dx) +. (vy *. dy) +. (vz *. dz) in
          let t = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
          if t -. (b *. b) <= tr.r2.(ch) then begin
            s.blob_bound_hits <- s.blob_bound_hits + 1;
            q.(!size) <- ch;
            incr size
          end
        done
    done
  end;
  !cnt

(* an element's quartic along the (shifted, scaled) ray, written at [5·index] of [fcoeffs] *)
let element_quartic (r : Scratch.blob_room) e px py pz dx dy dz max_bound =
  let t0, t1, t2 =
    match e.ekind with
    | Sphere ->
        let vx = px -. e.ox and vy = py -. e.oy and vz = pz -. e.oz in
        ((vx *. vx) +. (vy *. vy) +. (vz *. vz), (vx *. dx) +. (vy *. dy) +. (vz *. dz), max_bound *. max_bound)
    | Ellipsoid ->
        let vx = in_element e px py pz dx dy dz 0 -. e.ox and vy = in_element e px py pz dx dy dz 1 -. e.oy in
        let vz = in_element e px py pz dx dy dz 2 -. e.oz in
        let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
        ((vx *. vx) +. (vy *. vy) +. (vz *. vz), (vx *. ux) +. (vy *. uy) +. (vz *. uz), (ux *. ux) +. (uy *. uy) +. (uz *. uz))
    | Base_hemisphere | Apex_hemisphere ->
        let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 and qz = in_element e px py pz dx dy dz 2 in
        let qz = match e.ekind with Apex_hemisphere -> qz -. e.elen | Sphere | Ellipsoid | Base_hemisphere | Cylinder -> qz in
        let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 and uz = in_element e px py pz dx dy dz 5 in
        ((qx *. qx) +. (qy *. qy) +. (qz *. qz), (qx *. ux) +. (qy *. uy) +. (qz *. uz), (ux *. ux) +. (uy *. uy) +. (uz *. uz))
    | Cylinder ->
        let qx = in_element e px py pz dx dy dz 0 and qy = in_element e px py pz dx dy dz 1 in
        let ux = in_element e px py pz dx dy dz 3 and uy = in_element e px py pz dx dy dz 4 in
        ((qx *. qx) +. (qy *. qy), (qx *. ux) +. (qy *. uy), (ux *. ux) +. (uy *. uy))
  in
  let c0 = e.c0 and c1 = e.c1 and c2 = e.c2 in
  let f = r.fcoeffs and j = 5 * e.index in
  f.(j) <- c0 *. t2 *. t2;
  f.(j + 1) <- 4.0 *. c0 *. t1 *. t2;
  f.(j + 2) <- (2.0 *. c0 *. ((2.0 *. t1 *. t1) +. (t0 *. t2))) +. (c1 *. t2);
  f.(j + 3) <- 2.0 *. t1 *. ((2.0 *. c0 *. t0) +. c1);
  f.(j + 4) <- (t0 *. ((c0 *. t0) +. c1)) +. c2

let push_found (r : Scratch.blob_room) n t =
  if n >= Array.length r.found then begin
    let bigger = Array.make (2 * Array.length r.found) 0. in
    Array.blit r.found 0 bigger 0 n;
    r.found <- bigger
  end;
  r.found.(n) <- t;
  n + 1

(* one interval between two bounds: the Bézier hull test, then the quartic's roots within it *)
let interval (w : Scratch.t) (r : Scratch.blob_room) c bd i len start max_bound n =
  let acc = r.acc in
  let l = bd.(i) in
  let wd = bd.(i + 1) -. l in
  let c0 = acc.(0) and c1 = acc.(1) and c2 = acc.(2) and c3 = acc.(3) and c4 = acc.(4) in
  let n0 = c0 *. wd *. wd *. wd *. wd in
  let n1 = (c1 +. (4.0 *. c0 *. l)) *. wd *. wd *. wd in
  let n2 = ((3.0 *. l *. ((2.0 *. c0 *. l) +. c1)) +. c2) *. wd *. wd in
  let n3 = ((2.0 *. l *. ((2.0 *. l *. ((c0 *. l) +. (0.75 *. c1))) +. c2)) +. c3) *. wd in
  let n4 = (l *. ((l *. ((l *. ((c0 *. l) +. c1)) +. c2)) +. c3)) +. c4 in
  let dk0 = n4 in
  let dk1 = n4 +. (0.25 *. n3) in
  let dk2 = n4 +. (0.50 *. (n3 +. (n2 /. 3.0))) in
  let dk3 = n4 +. (0.50 *. ((1.5 *. n3) +. n2 +. (0.5 *. n1))) in
  let dk4 = n4 +. n3 +. n2 +. n1 +. n0 in
  if (dk0 >= 0.0 && dk1 >= 0.0 && dk2 >= 0.0 && dk3 >= 0.0 && dk4 >= 0.0) || (dk0 <= 0.0 && dk1 <= 0.0 && dk2 <= 0.0 && dk3 <= 0.0 && dk4 <= 0.0)
  then false
  else begin
    let s = w.stats in
    s.roots_tested <- s.roots_tested + 1;
    let k = Polysolv.solve w.quartic acc 4 ~sturm:c.csturm ~eps:root_epsilon w.roots in
    if Polysolv.eliminated w.quartic then s.roots_eliminated <- s.roots_eliminated + 1;
    let found = ref false in
    let mindist = if w.robust then 0. else depth_tolerance in
    for j = 0 to k - 1 do
      let dist = w.roots.(j) in
      if dist >= bd.(i) && dist <= bd.(i + 1) then begin
        let dist = ((dist *. max_bound) +. start) /. len in
        if dist > mindist && dist < max_distance then begin
          n := push_found r !n dist;
          found := true
        end
      end
    done;
    !found
  end

(* All_Intersections: the depths found, in [w.blob.found]; [child] (a CSG member) takes every
   interval, a blob on its own stops at the first one with a root, all later ones being farther *)
let intersect (w : Scratch.t) c ~child (o : Vec.t) (d : Vec.t) =
  let s = w.stats in
  s.blob_tests <- s.blob_tests + 1;
  let mindist = if w.robust then 0. else depth_tolerance in
  let px, py, pz, dx, dy, dz, len =
    match c.ctr with
    | Some m ->
        let px = (o.x *. m.i00) +. (o.y *. m.i10) +. (o.z *. m.i20) +. m.i30 in
        let py = (o.x *. m.i01) +. (o.y *. m.i11) +. (o.z *. m.i21) +. m.i31 in
        let pz = (o.x *. m.i02) +. (o.y *. m.i12) +. (o.z *. m.i22) +. m.i32 in
        let dx = (d.x *. m.i00) +. (d.y *. m.i10) +. (d.z *. m.i20) in
        let dy = (d.x *. m.i01) +. (d.y *. m.i11) +. (d.z *. m.i21) in
        let dz = (d.x *. m.i02) +. (d.y *. m.i12) +. (d.z *. m.i22) in
        let len = sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
        let k = 1. /. len in
        (px, py, pz, dx *. k, dy *. k, dz *. k, len)
    | None -> (o.x, o.y, o.z, d.x, d.y, d.z, 1.0)
  in
  let r = room w c in
  let cnt = influences w r c px py pz dx dy dz mindist in
  if cnt = 0 then 0
  else begin
    let bd = r.bounds and mk = r.marks in
    let start = if bd.(0) < small_tolerance then 0. else bd.(0) in
    for i = 0 to cnt - 1 do
      bd.(i) <- bd.(i) -. start
    done;
    let px = px +. (start *. dx) and py = py +. (start *. dy) and pz = pz +. (start *. dz) in
    let max_bound = ref bd.(0) in
    for i = 0 to cnt - 1 do
      if bd.(i) > !max_bound then max_bound := bd.(i)
    done;
    let dx, dy, dz, max_bound =
      if !max_bound <> 0. then begin
        let mb = !max_bound in
        for i = 0 to cnt - 1 do
          bd.(i) <- bd.(i) /. mb
        done;
        (dx *. mb, dy *. mb, dz *. mb, mb)
      end
      else (dx, dy, dz, 1.)
    in
    let acc = r.acc and f = r.fcoeffs in
    acc.(0) <- 0.;
    acc.(1) <- 0.;
    acc.(2) <- 0.;
    acc.(3) <- 0.;
    acc.(4) <- -.c.thresh;
    let n = ref 0 in
    let rec step i in_flag found =
      if i >= cnt then found
      else
        let e = c.elems.(mk.(i) lsr 1) in
        let j = 5 * e.index in
        let in_flag, skip =
          if mk.(i) land 1 = 0 then begin
            element_quartic r e px py pz dx dy dz max_bound;
            for k = 0 to 4 do
              acc.(k) <- acc.(k) +. f.(j + k)
            done;
            (in_flag + 1, false)
          end
          else begin
            for k = 0 to 4 do
              acc.(k) <- acc.(k) -. f.(j + k)
            done;
            (in_flag - 1, in_flag - 1 = 0)
          end
        in
        if skip || (i + 1 < cnt && Float.abs (bd.(i) -. bd.(i + 1)) < epsilon) then step (i + 1) in_flag found
        else
          let found = interval w r c bd i len start max_bound n || found in
          if found && not child then true else step (i + 1) in_flag found
    in
    let found = step 0 0 false in
    if found then s.blob_hits <- s.blob_hits + 1;
    !n
  end

(* ---------------------------------------------------------------------------------------------- *)
(* The field, its gradient and the components' weights at a point of blob space, every element
   visited as POV-Ray's hierarchy visits them (calculate_field_value, Normal, Determine_Textures). *)

let fold_near c (q : Vec.t) f init =
  let tr = c.tree in
  if tr.root < 0 then Array.fold_left f init c.elems
  else begin
    let q_ = Array.make (node_count c + 1) 0 in
    q_.(0) <- tr.root;
    let size = ref 1 and acc = ref init in
    while !size > 0 do
      decr size;
      let nd = q_.(!size) in
      let ne = tr.entries.(nd) in
      if ne <= 0 then acc := f !acc c.elems.(tr.first.(nd))
      else
        for j = 0 to ne - 1 do
          let ch = tr.kids.(tr.first.(nd) + j) in
          let vx = q.x -. tr.cx.(ch) and vy = q.y -. tr.cy.(ch) and vz = q.z -. tr.cz.(ch) in
          if (vx *. vx) +. (vy *. vy) +. (vz *. vz) <= tr.r2.(ch) then begin
            q_.(!size) <- ch;
            incr size
          end
        done
    done;
    !acc
  end

let[@inline] density e rad2 = (rad2 *. ((rad2 *. e.c0) +. e.c1)) +. e.c2

(* calculate_element_field *)
let element_field e (q : Vec.t) =
  match e.ekind with
  | Sphere ->
      let vx = q.x -. e.ox and vy = q.y -. e.oy and vz = q.z -. e.oz in
      let rad2 = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
      if rad2 < e.erad2 then density e rad2 else 0.
  | Ellipsoid ->
      let pp = Transform.inv_point e.etr q in
      let vx = pp.x -. e.ox and vy = pp.y -. e.oy and vz = pp.z -. e.oz in
      let rad2 = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
      if rad2 < e.erad2 then density e rad2 else 0.
  | Base_hemisphere ->
      let pp = Transform.inv_point e.etr q in
      if pp.z <= 0.0 then
        let rad2 = (pp.x *. pp.x) +. (pp.y *. pp.y) +. (pp.z *. pp.z) in
        if rad2 <= e.erad2 then density e rad2 else 0.
      else 0.
  | Apex_hemisphere ->
      let pp = Transform.inv_point e.etr q in
      let z = pp.z -. e.elen in
      if z >= 0.0 then
        let rad2 = (pp.x *. pp.x) +. (pp.y *. pp.y) +. (z *. z) in
        if rad2 <= e.erad2 then density e rad2 else 0.
      else 0.
  | Cylinder ->
      let pp = Transform.inv_point e.etr q in
      if pp.z >= 0.0 && pp.z <= e.elen then
        let rad2 = (pp.x *. pp.x) +. (pp.y *. pp.y) in
        if rad2 <= e.erad2 then density e rad2 else 0.
      else 0.

let local c (p : Vec.t) = match c.ctr with Some m -> Transform.inv_point m p | None -> p

let field c p =
  let q = local c p in
  fold_near c q (fun acc e -> acc +. element_field e q) 0.

let inside c p = field c p > c.thresh -. inside_tolerance

(* element_normal: the element's gradient term, added to [r] *)
let element_normal (r : Vec.t) e (q : Vec.t) =
  let add (r : Vec.t) v (n : Vec.t) = Vec.make (r.x +. (v *. n.x)) (r.y +. (v *. n.y)) (r.z +. (v *. n.z)) in
  let grad dist = (-2.0 *. e.c0 *. dist) -. e.c1 in
  match e.ekind with
  | Sphere ->
      let v1 = Vec.make (q.x -. e.ox) (q.y -. e.oy) (q.z -. e.oz) in
      let dist = (v1.x *. v1.x) +. (v1.y *. v1.y) +. (v1.z *. v1.z) in
      if dist <= e.erad2 then add r (grad dist) v1 else r
  | Ellipsoid ->
      let pp = Transform.inv_point e.etr q in
      let v1 = Vec.make (pp.x -. e.ox) (pp.y -. e.oy) (pp.z -. e.oz) in
      let dist = (v1.x *. v1.x) +. (v1.y *. v1.y) +. (v1.z *. v1.z) in
      if dist <= e.erad2 then add r (grad dist) (Transform.normal e.etr v1) else r
  | Base_hemisphere ->
      let pp = Transform.inv_point e.etr q in
      if pp.z <= 0.0 then
        let dist = (pp.x *. pp.x) +. (pp.y *. pp.y) +. (pp.z *. pp.z) in
        if dist <= e.erad2 then add r (grad dist) (Transform.normal e.etr pp) else r
      else r
  | Apex_hemisphere ->
      let pp = Transform.inv_point e.etr q in
      let pp = Vec.make pp.x pp.y (pp.z -. e.elen) in
      if pp.z >= 0.0 then
        let dist = (pp.x *. pp.x) +. (pp.y *. pp.y) +. (pp.z *. pp.z) in
        if dist <= e.erad2 then add r (grad dist) (Transform.normal e.etr pp) else r
      else r
  | Cylinder ->
      let pp = Transform.inv_point e.etr q in
      if pp.z >= 0.0 && pp.z <= e.elen then
        let dist = (pp.x *. pp.x) +. (pp.y *. pp.y) in
        if dist <= e.erad2 then add r (grad dist) (Transform.normal e.etr (Vec.make pp.x pp.y 0.0)) else r
      else r

let normal c p =
  let q = local c p in
  let r = fold_near c q (fun r e -> element_normal r e q) Vec.zero in
  let v = (r.x *. r.x) +. (r.y *. r.y) +. (r.z *. r.z) in
  let r =
    if v = 0.0 then Vec.make 1.0 0.0 0.0
    else
      let k = 1.0 /. sqrt v in
      Vec.make (r.x *. k) (r.y *. k) (r.z *. k)
  in
  match c.ctr with Some m -> Transform.normalize (Transform.normal m r) | None -> r

(* Determine_Textures: each element whose field is not 0 at the point, weighed by the field's
   magnitude (single precision, as POV-Ray's weights), the weights then scaled to sum to 1; an
   element without a texture of its own stands for the blob's ([−1]) *)
let weights c p =
  let f32 = Precision.f32 in
  let q = local c p in
  let found =
    List.rev
      (fold_near c q
         (fun acc e ->
           let d = Float.abs (element_field e q) in
           if d > 0.0 then (f32 d, e.etex) :: acc else acc)
         [])
  in
  match found with
  | [] -> []
  | _ ->
      let sum = List.fold_left (fun s (w, _) -> f32 (s +. w)) 0. found in
      let k = f32 (1.0 /. sum) in
      List.map (fun (w, t) -> (f32 (w *. k), t)) found

(* ---------------------------------------------------------------------------------------------- *)
(* What the tracer asks. *)

let near_limit (w : Scratch.t) = if w.robust then 0. else depth_tolerance

let depth (w : Scratch.t) c o d lo =
  let n = intersect w c ~child:false o d in
  let best = ref infinity in
  let f = w.blob.found in
  for i = n - 1 downto 0 do
    let x = f.(i) in
    if x < !best && x >= lo then best := x
  done;
  !best

let hits (w : Scratch.t) c id o d lo n =
  let k = intersect w c ~child:true o d in
  let n = ref n in
  for i = 0 to k - 1 do
    n := Scratch.push_ray w !n lo w.blob.found.(i) (-1) id o d
  done;
  !n

let bounds c = c.exact
let pov_box c = c.cbox

let stats_rows (s : Stats.t) =
  [
    { Stats.name = "Blob"; tests = s.blob_tests; hits = s.blob_hits };
    { Stats.name = "Blob Component"; tests = s.blob_element_tests; hits = s.blob_element_hits };
    { Stats.name = "Blob Bound"; tests = s.blob_bound_tests; hits = s.blob_bound_hits };
  ]

(* ---------------------------------------------------------------------------------------------- *)

let describe num vec b =
  let comp c =
    let kind = match c.kind with Sphere -> "sphere" | Ellipsoid -> "ellipsoid" | Cylinder -> "cylinder" | Base_hemisphere | Apex_hemisphere -> "hemisphere" in
    Printf.sprintf "\n  %s { %s, radius² %s, strength %s%s%s%s }" kind (vec c.origin) (num c.rad2) (num c.strength)
      (match c.kind with Cylinder -> ", length " ^ num c.len | Sphere | Ellipsoid | Base_hemisphere | Apex_hemisphere -> "")
      (if c.tex >= 0 then Printf.sprintf ", texture %d" c.tex else "")
      (match c.ctrans with None -> "" | Some t -> " " ^ Transform.to_string t)
  in
  Printf.sprintf "blob { threshold %s%s%s // %d components, the last written first%s%s" (num b.threshold) (if b.sturm then " sturm" else "")
    (if b.hierarchy then "" else " hierarchy off") (List.length b.components)
    (match b.box with Some x -> Printf.sprintf ", box <%s, %s, %s> + <%s, %s, %s>" (num x.(0)) (num x.(1)) (num x.(2)) (num x.(3)) (num x.(4)) (num x.(5)) | None -> "")
    (String.concat "" (List.map comp b.components))
