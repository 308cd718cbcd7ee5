(* POV-Ray's TRANSFORM (docs/povray-rules.md §14.1): M and its inverse I, 4×4, for row vectors. Products,
   inverses and point maps keep the operation order of POV-Ray's math/matrices.cpp (sums left to
   right, k = 0..3), because the last bit of a matrix entry can decide a pixel. Matrices are built
   in 16-float arrays (row-major) and stored in one all-float record, so that the tracer reads the
   entries unboxed. *)

type t = {
  m00 : float; m01 : float; m02 : float; m03 : float;
  m10 : float; m11 : float; m12 : float; m13 : float;
  m20 : float; m21 : float; m22 : float; m23 : float;
  m30 : float; m31 : float; m32 : float; m33 : float;
  i00 : float; i01 : float; i02 : float; i03 : float;
  i10 : float; i11 : float; i12 : float; i13 : float;
  i20 : float; i21 : float; i22 : float; i23 : float;
  i30 : float; i31 : float; i32 : float; i33 : float;
}

let epsilon = Precision.epsilon

(* π/180 as POV-Ray writes it (M_PI_180 = 0.01745329251994329576); the same double as pi /. 180. *)
let m_pi_180 = Float.pi /. 180.

let make (m : float array) (i : float array) =
  {
    m00 = m.(0); m01 = m.(1); m02 = m.(2); m03 = m.(3);
    m10 = m.(4); m11 = m.(5); m12 = m.(6); m13 = m.(7);
    m20 = m.(8); m21 = m.(9); m22 = m.(10); m23 = m.(11);
    m30 = m.(12); m31 = m.(13); m32 = m.(14); m33 = m.(15);
    i00 = i.(0); i01 = i.(1); i02 = i.(2); i03 = i.(3);
    i10 = i.(4); i11 = i.(5); i12 = i.(6); i13 = i.(7);
    i20 = i.(8); i21 = i.(9); i22 = i.(10); i23 = i.(11);
    i30 = i.(12); i31 = i.(13); i32 = i.(14); i33 = i.(15);
  }

let mat t =
  [| t.m00; t.m01; t.m02; t.m03; t.m10; t.m11; t.m12; t.m13; t.m20; t.m21; t.m22; t.m23; t.m30; t.m31; t.m32; t.m33 |]

let inv t =
  [| t.i00; t.i01; t.i02; t.i03; t.i10; t.i11; t.i12; t.i13; t.i20; t.i21; t.i22; t.i23; t.i30; t.i31; t.i32; t.i33 |]

let ident () = Array.init 16 (fun k -> if k mod 5 = 0 then 1. else 0.)
let identity = make (ident ()) (ident ())

(* a·b with each entry summed over k = 0..3 from left to right: both MTimesA (result·matrix2) and
   MTimesB (matrix1·result) compute exactly this. *)
let mul (a : float array) (b : float array) =
  Array.init 16 (fun k ->
      let r = 4 * (k / 4) and c = k mod 4 in
      (a.(r) *. b.(c)) +. (a.(r + 1) *. b.(4 + c)) +. (a.(r + 2) *. b.(8 + c)) +. (a.(r + 3) *. b.(12 + c)))

let transpose (a : float array) = Array.init 16 (fun k -> a.((4 * (k mod 4)) + (k / 4)))

let translate (v : Vec.t) =
  let m = ident () and i = ident () in
  m.(12) <- v.x; m.(13) <- v.y; m.(14) <- v.z;
  i.(12) <- -.v.x; i.(13) <- -.v.y; i.(14) <- -.v.z;
  make m i

let scale (v : Vec.t) =
  let m = ident () and i = ident () in
  m.(0) <- v.x; m.(5) <- v.y; m.(10) <- v.z;
  i.(0) <- 1. /. v.x; i.(5) <- 1. /. v.y; i.(10) <- 1. /. v.z;
  make m i

(* Compute_Rotation_Transform: M = Rx·Ry·Rz, I = Rzᵀ·Ryᵀ·Rxᵀ, each step a full 4×4 product;
   the off-diagonal sines are written "0.0 − s" (a +0 for s = 0). *)
let rotate (a : Vec.t) =
  let rx = a.x *. m_pi_180 and ry = a.y *. m_pi_180 and rz = a.z *. m_pi_180 in
  let cx = cos rx and sx = sin rx and cy = cos ry and sy = sin ry and cz = cos rz and sz = sin rz in
  let m = ident () in
  m.(5) <- cx; m.(10) <- cx; m.(6) <- sx; m.(9) <- 0. -. sx;
  let i = transpose m in
  let r = ident () in
  r.(0) <- cy; r.(10) <- cy; r.(2) <- 0. -. sy; r.(8) <- sy;
  let m = mul m r and i = mul (transpose r) i in
  let r = ident () in
  r.(0) <- cz; r.(5) <- cz; r.(1) <- sz; r.(4) <- 0. -. sz;
  let m = mul m r and i = mul (transpose r) i in
  make m i

(* Compute_Axis_Rotation_Transform's matrix for the unit axis (x, y, z) and the angle [a] in
   radians, built term by term; the inverse is its transpose. *)
let axis_matrix x y z a =
  let c = cos a and s = sin a in
  let m = ident () in
  m.(0) <- (x *. x) +. (c *. (1.0 -. (x *. x)));
  m.(1) <- (x *. y *. (1.0 -. c)) +. (z *. s);
  m.(2) <- (x *. z *. (1.0 -. c)) -. (y *. s);
  m.(4) <- (x *. y *. (1.0 -. c)) -. (z *. s);
  m.(5) <- (y *. y) +. (c *. (1.0 -. (y *. y)));
  m.(6) <- (y *. z *. (1.0 -. c)) +. (x *. s);
  m.(8) <- (x *. z *. (1.0 -. c)) +. (y *. s);
  m.(9) <- (y *. z *. (1.0 -. c)) -. (x *. s);
  m.(10) <- (z *. z) +. (c *. (1.0 -. (z *. z)));
  make m (transpose m)

(* Rotation by [deg] degrees about [axis] (Compute_Axis_Rotation_Transform, used by vaxis_rotate):
   the axis divided by its length. *)
let axis_rotate (axis : Vec.t) deg =
  let l = sqrt ((axis.x *. axis.x) +. (axis.y *. axis.y) +. (axis.z *. axis.z)) in
  axis_matrix (axis.x /. l) (axis.y /. l) (axis.z /. l) (deg *. m_pi_180)

(* MInvers: cofactor expansion, with POV-Ray's term order; None when the determinant is 0. *)
let invert (m : float array) =
  let m00 = m.(0) and m01 = m.(1) and m02 = m.(2) and m03 = m.(3) in
  let m10 = m.(4) and m11 = m.(5) and m12 = m.(6) and m13 = m.(7) in
  let m20 = m.(8) and m21 = m.(9) and m22 = m.(10) and m23 = m.(11) in
  let m30 = m.(12) and m31 = m.(13) and m32 = m.(14) and m33 = m.(15) in
  (* p a b c d e f g h i j k l = a·b·c + d·e·f + g·h·i − j·k·l − … , left to right *)
  let det a1 a2 a3 b1 b2 b3 c1 c2 c3 d1 d2 d3 e1 e2 e3 f1 f2 f3 =
    (a1 *. a2 *. a3) +. (b1 *. b2 *. b3) +. (c1 *. c2 *. c3) -. (d1 *. d2 *. d3) -. (e1 *. e2 *. e3) -. (f1 *. f2 *. f3)
  in
  let d00 = det m11 m22 m33 m12 m23 m31 m13 m21 m32 m31 m22 m13 m32 m23 m11 m33 m21 m12 in
  let d01 = det m10 m22 m33 m12 m23 m30 m13 m20 m32 m30 m22 m13 m32 m23 m10 m33 m20 m12 in
  let d02 = det m10 m21 m33 m11 m23 m30 m13 m20 m31 m30 m21 m13 m31 m23 m10 m33 m20 m11 in
  let d03 = det m10 m21 m32 m11 m22 m30 m12 m20 m31 m30 m21 m12 m31 m22 m10 m32 m20 m11 in
  let d10 = det m01 m22 m33 m02 m23 m31 m03 m21 m32 m31 m22 m03 m32 m23 m01 m33 m21 m02 in
  let d11 = det m00 m22 m33 m02 m23 m30 m03 m20 m32 m30 m22 m03 m32 m23 m00 m33 m20 m02 in
  let d12 = det m00 m21 m33 m01 m23 m30 m03 m20 m31 m30 m21 m03 m31 m23 m00 m33 m20 m01 in
  let d13 = det m00 m21 m32 m01 m22 m30 m02 m20 m31 m30 m21 m02 m31 m22 m00 m32 m20 m01 in
  let d20 = det m01 m12 m33 m02 m13 m31 m03 m11 m32 m31 m12 m03 m32 m13 m01 m33 m11 m02 in
  let d21 = det m00 m12 m33 m02 m13 m30 m03 m10 m32 m30 m12 m03 m32 m13 m00 m33 m10 m02 in
  let d22 = det m00 m11 m33 m01 m13 m30 m03 m10 m31 m30 m11 m03 m31 m13 m00 m33 m10 m01 in
  let d23 = det m00 m11 m32 m01 m12 m30 m02 m10 m31 m30 m11 m02 m31 m12 m00 m32 m10 m01 in
  let d30 = det m01 m12 m23 m02 m13 m21 m03 m11 m22 m21 m12 m03 m22 m13 m01 m23 m11 m02 in
  let d31 = det m00 m12 m23 m02 m13 m20 m03 m10 m22 m20 m12 m03 m22 m13 m00 m23 m10 m02 in
  let d32 = det m00 m11 m23 m01 m13 m20 m03 m10 m21 m20 m11 m03 m21 m13 m00 m23 m10 m01 in
  let d33 = det m00 m11 m22 m01 m12 m20 m02 m10 m21 m20 m11 m02 m21 m12 m00 m22 m10 m01 in
  let d = (m00 *. d00) -. (m01 *. d01) +. (m02 *. d02) -. (m03 *. d03) in
  if d = 0. then None
  else
    Some
      [| d00 /. d; -.d10 /. d; d20 /. d; -.d30 /. d;
         -.d01 /. d; d11 /. d; -.d21 /. d; d31 /. d;
         d02 /. d; -.d12 /. d; d22 /. d; -.d32 /. d;
         -.d03 /. d; d13 /. d; -.d23 /. d; d33 /. d |]

(* Parse_Matrix, then Compute_Matrix_Transform. *)
let matrix (a : float array) =
  if Array.length a <> 12 then invalid_arg "Transform.matrix: 12 numbers expected";
  let m = ident () in
  for r = 0 to 3 do
    for c = 0 to 2 do
      m.((4 * r) + c) <- a.((3 * r) + c)
    done
  done;
  let warnings = ref [] in
  for c = 0 to 2 do
    if Float.abs m.(c) < epsilon && Float.abs m.(4 + c) < epsilon && Float.abs m.(8 + c) < epsilon then begin
      warnings := "Illegal matrix column: Scale by 0.0. Changed to 1.0." :: !warnings;
      m.((4 * c) + c) <- 1.
    end
  done;
  match invert m with
  | None -> Error "Singular matrix in MInvers."
  | Some i -> Ok (make m i, List.rev !warnings)

(* Compose_Transforms(a, b): MTimesA(a.M, b.M), MTimesB(b.I, a.I). *)
let compose a b = make (mul (mat a) (mat b)) (mul (inv b) (inv a))

(* A transform set up from its inverse, the other matrix by MInvers (a polygon's frame, §15.7). *)
let of_inverse (i : float array) = Option.map (fun m -> make m (Array.copy i)) (invert i)

let product = mul
let inverse_matrix = inv

(* Parse_Transform_Block with inverse: MInvers on each matrix in place. *)
let inverse t =
  match (invert (mat t), invert (inv t)) with
  | Some m, Some i -> make m i
  | None, _ | _, None -> make (inv t) (mat t)

let[@inline] point t (p : Vec.t) =
  {
    Vec.x = (p.x *. t.m00) +. (p.y *. t.m10) +. (p.z *. t.m20) +. t.m30;
    y = (p.x *. t.m01) +. (p.y *. t.m11) +. (p.z *. t.m21) +. t.m31;
    z = (p.x *. t.m02) +. (p.y *. t.m12) +. (p.z *. t.m22) +. t.m32;
  }

let[@inline] direction t (p : Vec.t) =
  {
    Vec.x = (p.x *. t.m00) +. (p.y *. t.m10) +. (p.z *. t.m20);
    y = (p.x *. t.m01) +. (p.y *. t.m11) +. (p.z *. t.m21);
    z = (p.x *. t.m02) +. (p.y *. t.m12) +. (p.z *. t.m22);
  }

let[@inline] inv_point t (p : Vec.t) =
  {
    Vec.x = (p.x *. t.i00) +. (p.y *. t.i10) +. (p.z *. t.i20) +. t.i30;
    y = (p.x *. t.i01) +. (p.y *. t.i11) +. (p.z *. t.i21) +. t.i31;
    z = (p.x *. t.i02) +. (p.y *. t.i12) +. (p.z *. t.i22) +. t.i32;
  }

let[@inline] inv_direction t (p : Vec.t) =
  {
    Vec.x = (p.x *. t.i00) +. (p.y *. t.i10) +. (p.z *. t.i20);
    y = (p.x *. t.i01) +. (p.y *. t.i11) +. (p.z *. t.i21);
    z = (p.x *. t.i02) +. (p.y *. t.i12) +. (p.z *. t.i22);
  }

(* MTransNormal: rows of I, i.e. n·Iᵀ. *)
let[@inline] normal t (n : Vec.t) =
  {
    Vec.x = (n.x *. t.i00) +. (n.y *. t.i01) +. (n.z *. t.i02);
    y = (n.x *. t.i10) +. (n.y *. t.i11) +. (n.z *. t.i12);
    z = (n.x *. t.i20) +. (n.y *. t.i21) +. (n.z *. t.i22);
  }

let is_identity t = t = identity

(* VNormalize: VLength, then VInverseScale, which multiplies by 1/length. *)
let[@inline] normalize (v : Vec.t) =
  let k = 1. /. sqrt ((v.x *. v.x) +. (v.y *. v.y) +. (v.z *. v.z)) in
  { Vec.x = v.x *. k; y = v.y *. k; z = v.z *. k }

(* Recompute_BBox: the eight corners mapped, their extent clipped to ±BOUND_HUGE/2. *)
let bounds t (b : float array) =
  let lo = [| infinity; infinity; infinity |] and hi = [| neg_infinity; neg_infinity; neg_infinity |] in
  for k = 0 to 7 do
    let c = Vec.make (if k land 1 = 0 then b.(0) else b.(3)) (if k land 2 = 0 then b.(1) else b.(4)) (if k land 4 = 0 then b.(2) else b.(5)) in
    let p = point t c in
    let upd a v = lo.(a) <- Float.min lo.(a) v; hi.(a) <- Float.max hi.(a) v in
    upd 0 p.x; upd 1 p.y; upd 2 p.z
  done;
  let clip v = Float.max (-1e10) (Float.min 1e10 v) in
  [| clip lo.(0); clip lo.(1); clip lo.(2); clip hi.(0); clip hi.(1); clip hi.(2) |]

let to_string t =
  let m = mat t in
  String.concat "; "
    (List.init 4 (fun r -> Printf.sprintf "[%h %h %h %h]" m.(4 * r) m.((4 * r) + 1) m.((4 * r) + 2) m.((4 * r) + 3)))

(* Compute_Axis_Rotation_Transform: [angle] in radians, the axis normalised by VNormalize (times
   the reciprocal of its length), the inverse the transpose. *)
let axis_rotate_rad (axis : Vec.t) angle =
  let v = normalize axis in
  axis_matrix v.x v.y v.z angle

(* Compute_Coordinate_Transform (§15.2): scale <radius, radius, length>, then the rotation taking
   +z to [up] (about (−up.y, up.x, 0) by acos up.z; about x when up is within EPSILON of ±z, with
   up.z snapped to ±1), then translate [origin]. Returns the snapped [up] too: POV-Ray writes the
   snap back into the vector it was given (a disc keeps it as its normal). *)
let coordinate (origin : Vec.t) (up : Vec.t) radius length =
  let t = scale (Vec.make radius radius length) in
  let axis, up =
    if Float.abs up.z > 1.0 -. epsilon then (Vec.make 1. 0. 0., { up with z = (if up.z < 0. then -1. else 1.) })
    else (Vec.make (-.up.y) up.x 0., up)
  in
  let t = compose t (axis_rotate_rad axis (acos up.z)) in
  (compose t (translate origin), up)
