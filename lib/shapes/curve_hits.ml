(* The crossings of a prism, lathe or surface of revolution, collected as POV-Ray pushes them on
   its intersection stack, and the part code that carries a spline hit's segment and parameter to
   the normal. *)

(* the constants the three spline shapes share (prism.cpp, lathe.cpp, sor.cpp) and std::min and
   std::max: the first argument unless the second is strictly beyond it *)
module Limits = struct
  let epsilon = Precision.epsilon
  let max_distance = 1e7
  let depth_tolerance = 1e-4
  let bound_huge = 2e10
  let cmin a b = if b < a then b else a
  let cmax a b = if a < b then b else a
end

(* the near limit of a depth: DEPTH_TOLERANCE, none in the robust mode *)
let near_limit (w : Scratch.t) = if w.robust then 0. else Limits.depth_tolerance

(* the box of a shape of revolution (lathe, sor): −R2 … R2 across, height1 … height2 along Y *)
let revolution_box ~radius2 ~height1 ~height2 = [| -.radius2; height1; -.radius2; radius2; height2; radius2 |]

(* Lathe::Compute_BBox and Sor::Compute_BBox: Make_BBox in single precision, mapped *)
let revolution_pov_box tr ~radius2 ~height1 ~height2 =
  Pov_box.mapped tr (Array.map Precision.f32 [| -.radius2; height1; -.radius2; 2. *. radius2; height2 -. height1; 2. *. radius2 |])

let add (w : Scratch.t) k t part =
  let g = w.curve in
  if (2 * k) + 2 > Array.length g.room then begin
    let bigger = Array.make (2 * Array.length g.room) 0. in
    Array.blit g.room 0 bigger 0 (2 * k);
    g.room <- bigger
  end;
  g.room.(2 * k) <- t;
  g.room.((2 * k) + 1) <- Float.of_int part;
  k + 1

let nearest (w : Scratch.t) k lo = Scratch.nearest_pair w w.curve.room k lo

let push (w : Scratch.t) k id o d lo n =
  let h = w.curve.room in
  let n = ref n in
  for i = 0 to k - 1 do
    n := Scratch.push_ray w !n lo h.(2 * i) (int_of_float h.((2 * i) + 1)) id o d
  done;
  !n

(* 2^(50 − bits of the segment count): segment, parameter steps and the 3 plain parts stay below
   2^53, exact in the float of a CSG hit *)
let steps segments =
  let rec bits n b = if n = 0 then b else bits (n lsr 1) (b + 1) in
  Float.ldexp 1. (50 - bits (segments + 3) 0)

let spline_part ~segments j w = 3 + j + ((segments + 3) * int_of_float (Float.round (w *. steps segments)))

let segment ~segments part = (part - 3) mod (segments + 3)

let parameter ~segments part = Float.of_int ((part - 3) / (segments + 3)) /. steps segments

(* Trace::FindIntersection's ObjectBase::Intersect_BBox (Intersect_BBox_Dir): the single-precision
   box, the ray's origin and reciprocal direction in single precision, the slabs in single
   precision; a zero direction component makes 1/0 = ∞, and an origin on that slab's face plane
   makes 0·∞ = NaN, which fails every comparison: the object is not tried *)
let box_admits (b : float array) (o : Vec.t) (d : Vec.t) =
  Array.length b = 0
  ||
  let f = Precision.f32 in
  let mind = 1e-4 in
  let slab ll len on dn =
    let inv = f (1. /. dn) in
    let lo = ll and hi = f (ll +. len) in
    let o = f on in
    let a = f (f (lo -. o) *. inv) and b = f (f (hi -. o) *. inv) in
    if inv < 0. then (b, a) else (a, b)
  in
  let tmin, tmax = slab b.(0) b.(3) o.x d.x in
  let tymin, tymax = slab b.(1) b.(4) o.y d.y in
  (not (tmin > tymax || tymin > tmax))
  &&
  let tmin = if tymin > tmin then tymin else tmin in
  let tmax = if tymax < tmax then tymax else tmax in
  let tzmin, tzmax = slab b.(2) b.(5) o.z d.z in
  (not (tmin > tzmax || tzmin > tmax))
  &&
  let tmin = if tzmin > tmin then tzmin else tmin in
  let tmax = if tzmax < tmax then tzmax else tmax in
  tmin < infinity && tmax > mind
