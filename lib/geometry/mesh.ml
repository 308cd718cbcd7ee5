(* Triangle meshes as POV-Ray stores them (POVRAY-3.7 §2.6): single-precision vertices and normals,
   each face with its plane (the normal rounded to single precision, the distance kept in double),
   its dominant axis and swap, and a BVH over the faces. Built once; instances share it. *)

type t = {
  vertices : float array;  (* x y z per vertex, single-precision values *)
  normals : float array;  (* x y z per normal: vertex normals, then one per face *)
  tri_f : float array;  (* 4 per face: distance, Perp x y z *)
  tri_i : int array;  (* 9 per face: v1 v2 v3, face normal, n1 n2 n3 (−1: flat), axis·4 + vaxis, texture *)
  faces : int;
  bvh : Bvh.t;
  inside_vector : Vec.t option;  (* normalised; None: the mesh has no inside *)
}

type face = {
  corners : Vec.t * Vec.t * Vec.t;  (* the positions the set-up is computed from *)
  vi : int * int * int;  (* indices into [vertices] *)
  ni : (int * int * int) option;  (* indices into the vertex normals, for a smooth face *)
  tex : int;  (* index into the mesh's texture list, −1 for the mesh's own texture *)
}

let f32 x = Int32.float_of_bits (Int32.bits_of_float x)
let round_vec (v : Vec.t) = Vec.make (f32 v.x) (f32 v.y) (f32 v.z)

let build ~(vertices : float array) ~(vertex_normals : float array) ~(faces : face array) ~inside_vector =
  let nvn = Array.length vertex_normals / 3 in
  let vn i = Vec.make vertex_normals.(3 * i) vertex_normals.((3 * i) + 1) vertex_normals.((3 * i) + 2) in
  let tri_f = Array.make (4 * Array.length faces) 0. and tri_i = Array.make (9 * Array.length faces) 0 in
  let face_normals = Array.make (3 * Array.length faces) 0. in
  let n = ref 0 in
  Array.iter
    (fun f ->
      let p1, p2, p3 = f.corners in
      (* Compute_Mesh_Triangle: S = (P3 − P1) × (P2 − P1) *)
      let s = Vec.cross (Vec.sub p3 p1) (Vec.sub p2 p1) in
      let len = Vec.length s in
      if len > 0. then begin
        (* degenerate faces are dropped (§2.6) *)
        let s = Vec.make (s.x /. len) (s.y /. len) (s.z /. len) in
        let dist = -.Vec.dot s p1 in
        let axis = Triangle.max3_coordinate (Float.abs s.x) (Float.abs s.y) (Float.abs s.z) in
        let a, b, c = f.vi in
        let swap = Triangle.needs_swap axis p1 p2 p3 in
        let a, b, p1, p2 = if swap then (b, a, p2, p1) else (a, b, p1, p2) in
        let ns =
          match f.ni with
          | None -> None
          | Some (na, nb, nc) ->
              let na, nb = if swap then (nb, na) else (na, nb) in
              (* three equal normals make the face flat (§2.6) *)
              let d2 i j = Vec.length2 (Vec.sub (vn i) (vn j)) in
              if d2 na nb <= 1e-10 && d2 na nc <= 1e-10 then None else Some (na, nb, nc)
        in
        let perp, vaxis = Triangle.smooth_setup ~round:round_vec p1 p2 p3 in
        let k = !n in
        tri_f.(4 * k) <- dist;
        tri_f.((4 * k) + 1) <- perp.x;
        tri_f.((4 * k) + 2) <- perp.y;
        tri_f.((4 * k) + 3) <- perp.z;
        let s = round_vec s in
        face_normals.(3 * k) <- s.x;
        face_normals.((3 * k) + 1) <- s.y;
        face_normals.((3 * k) + 2) <- s.z;
        let o = 9 * k in
        tri_i.(o) <- a;
        tri_i.(o + 1) <- b;
        tri_i.(o + 2) <- c;
        tri_i.(o + 3) <- nvn + k;
        (match ns with
        | None -> tri_i.(o + 4) <- -1; tri_i.(o + 5) <- -1; tri_i.(o + 6) <- -1
        | Some (na, nb, nc) -> tri_i.(o + 4) <- na; tri_i.(o + 5) <- nb; tri_i.(o + 6) <- nc);
        tri_i.(o + 7) <- (axis * 4) + vaxis;
        tri_i.(o + 8) <- f.tex;
        incr n
      end)
    faces;
  let faces_n = !n in
  let tri_f = Array.sub tri_f 0 (4 * faces_n) and tri_i = Array.sub tri_i 0 (9 * faces_n) in
  let normals = Array.append vertex_normals (Array.sub face_normals 0 (3 * faces_n)) in
  let boxes = Array.make (6 * faces_n) 0. in
  for k = 0 to faces_n - 1 do
    for a = 0 to 2 do
      let v j = vertices.((3 * tri_i.((9 * k) + j)) + a) in
      boxes.((6 * k) + a) <- Float.min (v 0) (Float.min (v 1) (v 2));
      boxes.((6 * k) + 3 + a) <- Float.max (v 0) (Float.max (v 1) (v 2))
    done
  done;
  { vertices; normals; tri_f; tri_i; faces = faces_n; bvh = Bvh.build boxes; inside_vector = Option.map Vec.normalize inside_vector }

(* intersect_mesh_triangle: the depth of face [k], or infinity. *)
let[@inline] face_depth m k ox oy oz dx dy dz =
  let ni = 3 * m.tri_i.((9 * k) + 3) in
  let nx = m.normals.(ni) and ny = m.normals.(ni + 1) and nz = m.normals.(ni + 2) in
  let ndd = (nx *. dx) +. (ny *. dy) +. (nz *. dz) in
  if Float.abs ndd < 1e-10 then infinity
  else
    let ndo = (nx *. ox) +. (ny *. oy) +. (nz *. oz) in
    let depth = -.(m.tri_f.(4 * k) +. ndo) /. ndd in
    if depth < 1e-6 || depth > 1e7 then infinity
    else
      let v = m.vertices and o = 9 * k in
      let i1 = 3 * m.tri_i.(o) and i2 = 3 * m.tri_i.(o + 1) and i3 = 3 * m.tri_i.(o + 2) in
      let axis = m.tri_i.(o + 7) lsr 2 in
      let ua, wa, s, u =
        if axis = 0 then (1, 2, oy +. (depth *. dy), oz +. (depth *. dz))
        else if axis = 1 then (0, 2, ox +. (depth *. dx), oz +. (depth *. dz))
        else (0, 1, ox +. (depth *. dx), oy +. (depth *. dy))
      in
      let a1 = v.(i1 + ua) and b1 = v.(i1 + wa) and a2 = v.(i2 + ua) and b2 = v.(i2 + wa) and a3 = v.(i3 + ua) and b3 = v.(i3 + wa) in
      if (a2 -. s) *. (b2 -. b1) < (b2 -. u) *. (a2 -. a1)
         || (a3 -. s) *. (b3 -. b2) < (b3 -. u) *. (a3 -. a2)
         || (a1 -. s) *. (b1 -. b3) < (b1 -. u) *. (a1 -. a3)
      then infinity
      else depth

(* The nearest face hit with depth ≥ lo (mesh space, unit direction): its index, or −1; the depth is
   left in [hit.(0)]. Ties keep the first face found. *)
let nearest m stack (o : Vec.t) (d : Vec.t) lo hit =
  let best = ref infinity and idx = ref (-1) in
  Bvh.walk m.bvh stack o.x o.y o.z d.x d.y d.z infinity (fun k ->
      let t = face_depth m k o.x o.y o.z d.x d.y d.z in
      if t >= lo && t < !best then begin best := t; idx := k end;
      !best);
  hit.(0) <- !best;
  !idx

(* Whether some face is hit with lo ≤ depth < hi. *)
let any_hit m stack (o : Vec.t) (d : Vec.t) lo hi =
  let found = ref false in
  Bvh.walk m.bvh stack o.x o.y o.z d.x d.y d.z hi (fun k ->
      if !found then neg_infinity
      else
        let t = face_depth m k o.x o.y o.z d.x d.y d.z in
        if t >= lo && t < hi then (found := true; neg_infinity) else hi);
  !found

(* §2.6 Inside: an odd number of faces hit along the inside vector. *)
let inside m stack (p : Vec.t) =
  match m.inside_vector with
  | None -> false
  | Some d ->
      let count = ref 0 in
      Bvh.walk m.bvh stack p.x p.y p.z d.x d.y d.z infinity (fun k ->
          if face_depth m k p.x p.y p.z d.x d.y d.z < infinity then incr count;
          infinity);
      !count land 1 = 1

(* The normal of face [k] at the mesh-space point [p]: the interpolated vertex normal of a smooth
   face (normalised), or the stored single-precision face normal. *)
let normal m k (p : Vec.t) =
  let o = 9 * k in
  let n i = let j = 3 * i in Vec.make m.normals.(j) m.normals.(j + 1) m.normals.(j + 2) in
  if m.tri_i.(o + 4) < 0 then n m.tri_i.(o + 3)
  else
    let v = m.vertices in
    let i1 = 3 * m.tri_i.(o) in
    let dx = p.x -. v.(i1) and dy = p.y -. v.(i1 + 1) and dz = p.z -. v.(i1 + 2) in
    let u = (dx *. m.tri_f.((4 * k) + 1)) +. (dy *. m.tri_f.((4 * k) + 2)) +. (dz *. m.tri_f.((4 * k) + 3)) in
    let n1 = n m.tri_i.(o + 4) in
    if u < 1e-10 then Vec.normalize n1
    else
      let va = m.tri_i.(o + 7) land 3 in
      let pa = match va with 0 -> dx | 1 -> dy | _ -> dz in
      let k1 = v.(i1 + va) and k2 = v.((3 * m.tri_i.(o + 1)) + va) and k3 = v.((3 * m.tri_i.(o + 2)) + va) in
      let vv = ((pa /. u) +. k1 -. k2) /. (k3 -. k2) in
      let n2 = n m.tri_i.(o + 5) and n3 = n m.tri_i.(o + 6) in
      let f a1 a2 a3 = a1 +. (u *. (a2 -. a1 +. (vv *. (a3 -. a2)))) in
      Vec.normalize (Vec.make (f n1.x n2.x n3.x) (f n1.y n2.y n3.y) (f n1.z n2.z n3.z))

let texture m k = m.tri_i.((9 * k) + 8)

let bounds m =
  if m.faces = 0 then [| 0.; 0.; 0.; 0.; 0.; 0. |] else Array.sub m.bvh.boxes 0 6
