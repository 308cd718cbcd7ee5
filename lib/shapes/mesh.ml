(* Triangle meshes as POV-Ray stores them (docs/povray-rules.md §2.6): single-precision vertices and normals,
   each face with its plane (normal and distance computed in double, both stored in single
   precision: MESH_TRIANGLE's Distance is an SNGL),
   its dominant axis and swap, and a BVH over the faces. Built once; instances share it. The
   single-precision data is stored in single precision, which also halves its memory. *)

open Bigarray

type f32s = (float, float32_elt, c_layout) Array1.t
type i32s = (int32, int32_elt, c_layout) Array1.t

type t = {
  vertices : f32s;  (* x y z per vertex *)
  vnormals : f32s;  (* x y z per vertex normal *)
  fgeom : f32s;  (* 6 per face: face normal x y z, Perp x y z *)
  fdist : float array;  (* 1 per face: plane distance, a single-precision value *)
  fidx : i32s;  (* 7 per face: v1 v2 v3, n1 n2 n3 (−1: flat), axis + 4·vaxis + 16·(texture + 1) *)
  faces : int;
  bvh : Bvh.t;
  inside_vector : Vec.t option;  (* normalised; None: the mesh has no inside *)
  uvs : float array;  (* u v per UV coordinate, in double precision (UV_VECT); empty: every corner's is (0, 0) *)
  fuv : i32s;  (* 3 per face: the corners' UV indices, swapped with the vertices; empty: every corner's is UV 0 *)
}

let f32 = Precision.f32
let round_vec (v : Vec.t) = Vec.make (f32 v.x) (f32 v.y) (f32 v.z)
let[@inline] fget (a : f32s) i = Array1.unsafe_get a i
let[@inline] iget (a : i32s) i = Int32.to_int (Array1.unsafe_get a i)

let f32s_of_array a =
  let b = Array1.create float32 c_layout (Array.length a) in
  Array.iteri (fun i x -> Array1.unsafe_set b i x) a;
  b

let build_uv ~uvs ~(fuv : int array) ~(vertices : float array) ~(vertex_normals : float array) ~(fv : int array) ~(fn : int array)
    ~(ftex : int array) ~(corners : float array option) ~inside_vector =
  let nf = Array.length fv / 3 in
  let with_uv = Array.length fuv > 0 in
  let fuvb = Array1.create int32 c_layout (if with_uv then 3 * nf else 0) in
  let tex f = if Array.length ftex = 0 then -1 else ftex.(f) in
  let vn i = Vec.make vertex_normals.(3 * i) vertex_normals.((3 * i) + 1) vertex_normals.((3 * i) + 2) in
  let vx i = Vec.make vertices.(3 * i) vertices.((3 * i) + 1) vertices.((3 * i) + 2) in
  let corner f j =
    match corners with
    | Some c -> Vec.make c.((9 * f) + (3 * j)) c.((9 * f) + (3 * j) + 1) c.((9 * f) + (3 * j) + 2)
    | None -> vx fv.((3 * f) + j)
  in
  let fgeom = Array1.create float32 c_layout (6 * nf) and fdist = Array.make nf 0. in
  let fidx = Array1.create int32 c_layout (7 * nf) in
  let seti i x = Array1.unsafe_set fidx i (Int32.of_int x) in
  let n = ref 0 in
  for f = 0 to nf - 1 do
    let p1 = corner f 0 and p2 = corner f 1 and p3 = corner f 2 in
    (* Compute_Mesh_Triangle: S = (P3 − P1) × (P2 − P1) *)
    let s = Vec.cross (Vec.sub p3 p1) (Vec.sub p2 p1) in
    let len = Vec.length s in
    if len > 0. then begin
      (* degenerate faces are dropped (§2.6) *)
      let s = Vec.scale (1. /. len) s in
      let dist = -.Vec.dot s p1 in
      let axis = Triangle.max3_coordinate (Float.abs s.x) (Float.abs s.y) (Float.abs s.z) in
      let a = fv.(3 * f) and b = fv.((3 * f) + 1) and c = fv.((3 * f) + 2) in
      let swap = Triangle.needs_swap axis p1 p2 p3 in
      let a, b, p1, p2 = if swap then (b, a, p2, p1) else (a, b, p1, p2) in
      let flat_only = Array.length fn = 0 in
      let na = if flat_only then -1 else fn.(3 * f) and nb = if flat_only then -1 else fn.((3 * f) + 1) in
      let nc = if flat_only then -1 else fn.((3 * f) + 2) in
      let na, nb = if swap then (nb, na) else (na, nb) in
      (* three equal normals make the face flat (§2.6) *)
      let smooth =
        na >= 0
        &&
        let d2 i j = Vec.length2 (Vec.sub (vn i) (vn j)) in
        not (d2 na nb <= 1e-10 && d2 na nc <= 1e-10)
      in
      let perp, vaxis = Triangle.smooth_setup ~round:round_vec p1 p2 p3 in
      let k = !n in
      (* SNGL Distance: far from the origin this rounding moves the plane by up to half a float
         step of the coordinates (4e-3 at 1e5) *)
      fdist.(k) <- f32 dist;
      let g = 6 * k in
      Array1.unsafe_set fgeom g s.x;
      Array1.unsafe_set fgeom (g + 1) s.y;
      Array1.unsafe_set fgeom (g + 2) s.z;
      Array1.unsafe_set fgeom (g + 3) perp.x;
      Array1.unsafe_set fgeom (g + 4) perp.y;
      Array1.unsafe_set fgeom (g + 5) perp.z;
      let o = 7 * k in
      seti o a;
      seti (o + 1) b;
      seti (o + 2) c;
      seti (o + 3) (if smooth then na else -1);
      seti (o + 4) (if smooth then nb else -1);
      seti (o + 5) (if smooth then nc else -1);
      seti (o + 6) (axis + (4 * vaxis) + (16 * (tex f + 1)));
      if with_uv then begin
        (* Compute_Mesh_Triangle swaps UV1 and UV2 with P1 and P2 *)
        let ua = fuv.(3 * f) and ub = fuv.((3 * f) + 1) in
        let ua, ub = if swap then (ub, ua) else (ua, ub) in
        Array1.unsafe_set fuvb (3 * k) (Int32.of_int ua);
        Array1.unsafe_set fuvb ((3 * k) + 1) (Int32.of_int ub);
        Array1.unsafe_set fuvb ((3 * k) + 2) (Int32.of_int fuv.((3 * f) + 2))
      end;
      incr n
    end
  done;
  let faces = !n in
  let fgeom = if faces = nf then fgeom else Array1.sub fgeom 0 (6 * faces) in
  let fidx = if faces = nf then fidx else Array1.sub fidx 0 (7 * faces) in
  let fdist = if faces = nf then fdist else Array.sub fdist 0 faces in
  let fuv = if faces = nf || not with_uv then fuvb else Array1.sub fuvb 0 (3 * faces) in
  let boxes = Bvh.create_boxes faces in
  for k = 0 to faces - 1 do
    let v j a = vertices.((3 * iget fidx ((7 * k) + j)) + a) in
    let lo a = Float.min (v 0 a) (Float.min (v 1 a) (v 2 a)) and hi a = Float.max (v 0 a) (Float.max (v 1 a) (v 2 a)) in
    Bvh.set_box boxes k (lo 0) (lo 1) (lo 2) (hi 0) (hi 1) (hi 2)
  done;
  let bvh = Bvh.build boxes in
  {
    vertices = f32s_of_array vertices;
    vnormals = f32s_of_array vertex_normals;
    fgeom;
    fdist;
    fidx;
    faces;
    bvh;
    inside_vector = Option.map Vec.normalize inside_vector;
    uvs;
    fuv;
  }

let build = build_uv ~uvs:[||] ~fuv:[||]

(* intersect_mesh_triangle: the depth of face [k], or infinity. *)
let face_depth (lim : Limits.t) m k ox oy oz dx dy dz =
  let g = 6 * k in
  let nx = fget m.fgeom g and ny = fget m.fgeom (g + 1) and nz = fget m.fgeom (g + 2) in
  let ndd = (nx *. dx) +. (ny *. dy) +. (nz *. dz) in
  if Float.abs ndd < 1e-10 then infinity
  else
    let ndo = (nx *. ox) +. (ny *. oy) +. (nz *. oz) in
    let depth = -.(Array.unsafe_get m.fdist k +. ndo) /. ndd in
    if depth < lim.near || depth > lim.far then infinity
    else
      let v = m.vertices and o = 7 * k in
      let i1 = 3 * iget m.fidx o and i2 = 3 * iget m.fidx (o + 1) and i3 = 3 * iget m.fidx (o + 2) in
      let axis = iget m.fidx (o + 6) land 3 in
      (* the projection drops the dominant axis: (ua, wa) are the two kept *)
      let ua = if axis = 0 then 1 else 0 and wa = if axis = 2 then 1 else 2 in
      let s = if axis = 0 then oy +. (depth *. dy) else ox +. (depth *. dx) in
      let u = if axis = 2 then oy +. (depth *. dy) else oz +. (depth *. dz) in
      let a1 = fget v (i1 + ua) and b1 = fget v (i1 + wa) and a2 = fget v (i2 + ua) and b2 = fget v (i2 + wa) in
      let a3 = fget v (i3 + ua) and b3 = fget v (i3 + wa) in
      if (a2 -. s) *. (b2 -. b1) < (b2 -. u) *. (a2 -. a1)
         || (a3 -. s) *. (b3 -. b2) < (b3 -. u) *. (a3 -. a2)
         || (a1 -. s) *. (b1 -. b3) < (b1 -. u) *. (a1 -. a3)
      then infinity
      else depth

(* The nearest face hit with depth ≥ lo (mesh space, unit direction): its index, or −1; the depth is
   left in [hit.(0)]. Ties keep the first face found. *)
let nearest_within lim m stack (o : Vec.t) (d : Vec.t) lo hit =
  let best = ref infinity and idx = ref (-1) in
  Bvh.walk m.bvh stack o.x o.y o.z d.x d.y d.z infinity (fun k ->
      let t = face_depth lim m k o.x o.y o.z d.x d.y d.z in
      if t >= lo && t < !best then begin best := t; idx := k end;
      !best);
  hit.(0) <- !best;
  !idx

let nearest m stack o d lo hit = nearest_within Limits.pov m stack o d lo hit

(* Every face crossed, in the order the hierarchy is walked (Mesh::All_Intersections). *)
let iter_hits lim m stack (o : Vec.t) (d : Vec.t) f =
  Bvh.walk m.bvh stack o.x o.y o.z d.x d.y d.z infinity (fun k ->
      let t = face_depth lim m k o.x o.y o.z d.x d.y d.z in
      if t < infinity then f k t;
      infinity)

(* Whether some face is hit with lo ≤ depth < hi. *)
let any_hit m stack (o : Vec.t) (d : Vec.t) lo hi =
  let found = ref false in
  Bvh.walk m.bvh stack o.x o.y o.z d.x d.y d.z hi (fun k ->
      if !found then neg_infinity
      else
        let t = face_depth Limits.pov m k o.x o.y o.z d.x d.y d.z in
        if t >= lo && t < hi then (found := true; neg_infinity) else hi);
  !found

(* §2.6 Inside: an odd number of faces hit from [p] along [d]. *)
let inside_along m stack (p : Vec.t) (d : Vec.t) =
  match m.inside_vector with
  | None -> false
  | Some _ ->
      let count = ref 0 in
      Bvh.walk m.bvh stack p.x p.y p.z d.x d.y d.z infinity (fun k ->
          if face_depth Limits.pov m k p.x p.y p.z d.x d.y d.z < infinity then incr count;
          infinity);
      !count land 1 = 1

let inside m stack p = match m.inside_vector with None -> false | Some d -> inside_along m stack p d

(* The normal of face [k] at the mesh-space point [p], not normalised: the interpolated vertex
   normal of a smooth face (Smooth_Mesh_Normal), or the stored single-precision face normal. *)
let raw_normal m k (p : Vec.t) =
  let o = 7 * k and g = 6 * k in
  let n i = let j = 3 * i in Vec.make (fget m.vnormals j) (fget m.vnormals (j + 1)) (fget m.vnormals (j + 2)) in
  if iget m.fidx (o + 3) < 0 then Vec.make (fget m.fgeom g) (fget m.fgeom (g + 1)) (fget m.fgeom (g + 2))
  else
    let v = m.vertices in
    let i1 = 3 * iget m.fidx o in
    let dx = p.x -. fget v i1 and dy = p.y -. fget v (i1 + 1) and dz = p.z -. fget v (i1 + 2) in
    let u = (dx *. fget m.fgeom (g + 3)) +. (dy *. fget m.fgeom (g + 4)) +. (dz *. fget m.fgeom (g + 5)) in
    let n1 = n (iget m.fidx (o + 3)) in
    if u < 1e-10 then n1
    else
      let va = (iget m.fidx (o + 6) lsr 2) land 3 in
      let pa = match va with 0 -> dx | 1 -> dy | _ -> dz in
      let k1 = fget v (i1 + va) and k2 = fget v ((3 * iget m.fidx (o + 1)) + va) and k3 = fget v ((3 * iget m.fidx (o + 2)) + va) in
      let vv = ((pa /. u) +. k1 -. k2) /. (k3 -. k2) in
      let n2 = n (iget m.fidx (o + 4)) and n3 = n (iget m.fidx (o + 5)) in
      let f a1 a2 a3 = a1 +. (u *. (a2 -. a1 +. (vv *. (a3 -. a2)))) in
      Vec.make (f n1.x n2.x n3.x) (f n1.y n2.y n3.y) (f n1.z n2.z n3.z)

let is_smooth m k = iget m.fidx ((7 * k) + 3) >= 0

(* The normal of face [k] at the mesh-space point [p]: the interpolated vertex normal of a smooth
   face (normalised), or the stored single-precision face normal. *)
let normal m k (p : Vec.t) = if is_smooth m k then Vec.normalize (raw_normal m k p) else raw_normal m k p

let texture m k = (iget m.fidx ((7 * k) + 6) lsr 4) - 1

(* The UV coordinate of corner [j] (0, 1, 2) of face [k]: u is [uv_part 0], v [uv_part 1]. *)
let corner_uv m k j part =
  if Array1.dim m.fuv > 0 then Array.unsafe_get m.uvs ((2 * iget m.fuv ((3 * k) + j)) + part)
  else if Array.length m.uvs > 0 then m.uvs.(part)
  else 0.

(* Mesh::UVCoord at the mesh-space point [p]: each corner's weight is 1 + t1/t2, from the
   projection of the point onto the height of the triangle over the opposite side, and the
   corners' UV coordinates are blended by the weights. The vertices are the single-precision
   ones. *)
let uv m k (p : Vec.t) =
  let v = m.vertices and o = 7 * k in
  let vx i = let j = 3 * iget m.fidx (o + i) in Vec.make (fget v j) (fget v (j + 1)) (fget v (j + 2)) in
  let p1 = vx 0 and p2 = vx 1 and p3 = vx 2 in
  (* the weight of the corner [a] with the side [b]–[c] opposite: Side1 = c − b, Side2 = c − a *)
  let weight (a : Vec.t) (b : Vec.t) (c : Vec.t) =
    let side1 = Vec.sub c b and side2 = Vec.sub c a in
    let va = Vec.sub p a in
    let t1 = Vec.dot side2 side1 and t2 = Vec.dot side1 side1 in
    let vb = Vec.sub (Vec.scale (t1 /. t2) side1) side2 in
    let t1 = Vec.dot va vb and t2 = Vec.dot vb vb in
    1. +. (t1 /. t2)
  in
  let w1 = weight p1 p2 p3 and w2 = weight p2 p1 p3 and w3 = weight p3 p1 p2 in
  let blend part = (w1 *. corner_uv m k 0 part) +. (w2 *. corner_uv m k 1 part) +. (w3 *. corner_uv m k 2 part) in
  Vec.make (blend 0) (blend 1) 0.

(* Compute_Mesh_BBox: the extent of the (single-precision) corners of the faces. *)
let extent m =
  let lo = [| infinity; infinity; infinity |] and hi = [| neg_infinity; neg_infinity; neg_infinity |] in
  for k = 0 to (3 * m.faces) - 1 do
    let i = 3 * iget m.fidx (((k / 3) * 7) + (k mod 3)) in
    for a = 0 to 2 do
      let x = fget m.vertices (i + a) in
      if x < lo.(a) then lo.(a) <- x;
      if x > hi.(a) then hi.(a) <- x
    done
  done;
  if m.faces = 0 then [| 0.; 0.; 0.; 0.; 0.; 0. |] else Array.append lo hi

let bounds m =
  if m.faces = 0 then [| 0.; 0.; 0.; 0.; 0.; 0. |]
  else Array.init 6 (fun i -> if i < 3 then Bvh.box_min m.bvh i else Bvh.box_max m.bvh (i - 3))

let face_normal m k =
  let g = 6 * k in
  Vec.make (fget m.fgeom g) (fget m.fgeom (g + 1)) (fget m.fgeom (g + 2))

type placed = { mesh : t; tr : Transform.t; moved : bool }

let place mesh = function None -> { mesh; tr = Transform.identity; moved = false } | Some tr -> { mesh; tr; moved = true }

(* Mesh::Intersect: a moved mesh is searched in its own space with the direction renormalised
   (times the reciprocal length), and the depth is divided by that length *)
let depth (w : Scratch.t) m (o : Vec.t) (d : Vec.t) lo =
  let stats = w.stats in
  Stats.test stats Stats.mesh;
  let k, depth =
    if not m.moved then
      let k = nearest_within w.lim m.mesh w.mesh_stack o d lo w.mesh_depth in
      (k, w.mesh_depth.(0))
    else
      let v = Transform.inv_direction m.tr d in
      let len = Vec.length v in
      let k = nearest_within w.lim m.mesh w.mesh_stack (Transform.inv_point m.tr o) (Vec.scale (1. /. len) v) (lo *. len) w.mesh_depth in
      (k, w.mesh_depth.(0) /. len)
  in
  if k >= 0 && depth >= lo then begin
    Stats.hit stats Stats.mesh;
    w.part <- k;
    depth
  end
  else infinity

let hits (w : Scratch.t) m id (o : Vec.t) (d : Vec.t) lo n =
  let stats = w.stats and lim = w.lim in
  Stats.test stats Stats.mesh;
  let count = ref n in
  let n0 = n in
  (if not m.moved then iter_hits lim m.mesh w.mesh_stack o d (fun k t -> count := Scratch.push_ray w !count lo t k id o d)
   else
     let v = Transform.inv_direction m.tr d in
     let len = Vec.length v in
     iter_hits lim m.mesh w.mesh_stack (Transform.inv_point m.tr o) (Vec.scale (1. /. len) v) (fun k t ->
         count := Scratch.push_ray w !count lo (t /. len) k id o d));
  if !count > n0 then Stats.hit stats Stats.mesh;
  !count

(* Mesh::Normal: with a transform, the unnormalised mesh-space normal by the inverse transpose,
   normalised once (§2.6, §14.6) *)
let placed_normal m face (p : Vec.t) =
  if m.moved then Transform.normalize (Transform.normal m.tr (raw_normal m.mesh face (Transform.inv_point m.tr p)))
  else normal m.mesh face p

let placed_face_normal m face =
  if m.moved then Transform.normalize (Transform.normal m.tr (face_normal m.mesh face)) else face_normal m.mesh face

(* Mesh::Inside: the ray from P along the inside vector, both brought into mesh space and the
   direction renormalised *)
let placed_inside stack m p =
  if not m.moved then inside m.mesh stack p
  else
    match m.mesh.inside_vector with
    | None -> false
    | Some d -> inside_along m.mesh stack (Transform.inv_point m.tr p) (Transform.normalize (Transform.inv_direction m.tr d))

(* Mesh::UVCoord: the world point brought into mesh space when the mesh is moved *)
let placed_uv m face p = uv m.mesh face (if m.moved then Transform.inv_point m.tr p else p)

let placed_bounds m = if m.moved then Transform.bounds m.tr (bounds m.mesh) else bounds m.mesh

let placed_pov_box m =
  let b = Pov_box.of_min_max (Array.sub (extent m.mesh) 0 3) (Array.sub (extent m.mesh) 3 3) in
  if m.moved then Pov_box.mapped m.tr b else b

let traits = { Traits.default with name = "mesh"; costly = false }
