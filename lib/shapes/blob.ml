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
let depth_tolerance = 1e-2 (* DEPTH_TOLERANCE of blob.cpp *)
let inside_tolerance = 1e-6 (* INSIDE_TOLERANCE *)

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
(* The compiled blob. *)

type compiled = {
  elems : element array;
  thresh : float;
  csturm : bool;
  ctr : Transform.t option;
  tree : Blob_tree.t;
  cbox : float array;
  exact : float array;  (** the box in doubles: blob-space extent mapped by the transform *)
  textured : bool;  (** some component has a texture of its own (MULTITEXTURE_FLAG) *)
}

let compile (b : t) =
  let elems = elements_of b in
  let tree = if not b.hierarchy then Blob_tree.none else Blob_tree.build (Array.map bounding_sphere elems) in
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

(* ---------------------------------------------------------------------------------------------- *)
(* The field, its gradient and the components' weights at a point of blob space, every element
   visited as POV-Ray's hierarchy visits them (calculate_field_value, Normal, Determine_Textures). *)

let node_count c = Array.length c.tree.entries

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

let bounds c = c.exact
let pov_box c = c.cbox

let traits = { Traits.default with name = "blob"; sturm = Sturm_float }

(* ---------------------------------------------------------------------------------------------- *)

let describe num vec matrix b =
  let comp c =
    let kind = match c.kind with Sphere -> "sphere" | Ellipsoid -> "ellipsoid" | Cylinder -> "cylinder" | Base_hemisphere | Apex_hemisphere -> "hemisphere" in
    Printf.sprintf "\n  %s { %s, radius² %s, strength %s%s%s%s }" kind (vec c.origin) (num c.rad2) (num c.strength)
      (match c.kind with Cylinder -> ", length " ^ num c.len | Sphere | Ellipsoid | Base_hemisphere | Apex_hemisphere -> "")
      (if c.tex >= 0 then Printf.sprintf ", texture %d" c.tex else "")
      (match c.ctrans with None -> "" | Some t -> " " ^ matrix t)
  in
  Printf.sprintf "blob { threshold %s%s%s // %d components, the last written first%s%s" (num b.threshold) (if b.sturm then " sturm" else "")
    (if b.hierarchy then "" else " hierarchy off") (List.length b.components)
    (match b.box with Some x -> Printf.sprintf ", box <%s, %s, %s> + <%s, %s, %s>" (num x.(0)) (num x.(1)) (num x.(2)) (num x.(3)) (num x.(4)) (num x.(5)) | None -> "")
    (String.concat "" (List.map comp b.components))
