(* The value of every pattern (pattern.cpp's Evaluate_TPat, before frequency, phase and wave);
   §17.4–§17.7 for checker, gradient, hexagon and brick. Every formula keeps POV-Ray's order of
   floating-point operations, its constants as written and its C conversions, so that a value here
   is the double POV-Ray computes. *)

type hit = { normal : Vec.t; dir : Vec.t }

let no_hit = { normal = Vec.make 0. 1. 0.; dir = Vec.make 0. 0. 1. }

(* ---------------------------------------------------------------------------------------------- *)
(* C's arithmetic *)

(* C's (int) cast of a double: truncation; NaN and values out of range give INT_MIN, as the x86
   conversion instruction does *)
let c_int x = if Float.is_nan x || Float.abs x >= 2147483648. then -2147483648 else int_of_float x

(* std::max and std::min as POV-Ray calls them: the first argument unless the comparison says
   otherwise, which decides NaNs and signed zeros *)
let[@inline] fmax (a : float) b = if a < b then b else a
let[@inline] fmin (a : float) b = if b < a then b else a
let[@inline] max3 a b c = fmax a (fmax b c)

(* CLIP_DENSITY: 1 − r inside [0, 1], 1 below and 0 above *)
let[@inline] clip_density r = if r < 0. then 1. else if r > 1. then 0. else 1. -. r

(* POV-Ray's FLOOR macro, which for a negative integer gives one less than floor *)
let[@inline] pov_floor x = if x >= 0. then floor x else 0. -. floor (0. -. x) -. 1.

let two_pi = 6.283185307179586476925286766560
let half_pi = 1.57079632679489661923

(* cycloidal (texture.cpp): sin(2π·frac v), the fraction scaled by 50000 and back first *)
let cycloidal v =
  if v >= 0. then sin ((v -. floor v) *. 50000. /. 50000. *. two_pi)
  else 0. -. sin ((0. -. (v +. floor (0. -. v))) *. 50000. /. 50000. *. two_pi)

(* Triangle_Wave (texture.cpp) *)
let triangle_wave v =
  let offset = if v >= 0. then v -. floor v else v +. 1. +. floor (Float.abs v) in
  if offset >= 0.5 then 2. *. (1. -. offset) else 2. *. offset

(* The turbulence Check_Turb creates for agate when none is written: amount 0, 6 octaves *)
let default_turb = { Scene.turbulence = Vec.zero; octaves = 6; omega = 0.5; lambda = 2. }

(* ---------------------------------------------------------------------------------------------- *)
(* §17.4–§17.7 *)

(* §17.4: a coordinate that is an integer, or within 1e-10 below one, belongs to the cell above *)
let checker (q : Vec.t) =
  let s = Precision.(floor (q.x +. epsilon) +. floor (q.y +. epsilon) +. floor (q.z +. epsilon)) in
  if c_int s land 1 = 1 then 1. else 0.

(* pattern.cpp object_pattern: 1 inside the object (Inside_Object: inside every clip object, then
   the object's own Inside test), else 0 *)
let object_pattern (t : Scene.object_test) (q : Vec.t) = if t.inside q then 1. else 0.

(* §17.5: values up to 1 (negatives included) pass unchanged; the wrap of §17.1 does the rest *)
let gradient (v : Vec.t) (q : Vec.t) =
  let r = (q.x *. v.x) +. (q.y *. v.y) +. (q.z *. v.z) in
  if r > 1. then Float.rem r 1. else r

(* §17.6: the cell of a hexagonal tiling of the XZ plane, in a 6×6 grid of half-unit columns and
   rows of √3/2 *)
let hexagon (q : Vec.t) =
  let x = Float.abs q.x in
  let z = if q.z < 0. then 5.196152424 -. Float.abs q.z else q.z in
  let xs = x /. 0.5 and zs = z /. 0.866025404 in
  let xs = xs -. (6. *. floor (xs /. 6.)) and zs = zs -. (6. *. floor (zs /. 6.)) in
  let xm = int_of_float (floor xs) mod 6 and zm = int_of_float (floor zs) mod 6 in
  match xm with
  | 0 | 5 -> ( match zm with 0 | 5 -> 0. | 1 | 2 -> 1. | _ -> 2.)
  | 2 | 3 -> ( match zm with 0 | 1 -> 2. | 2 | 3 -> 0. | _ -> 1.)
  | _ ->
      let xl = xs -. float_of_int xm and zl = zs -. float_of_int zm in
      let xl = if (xm + zm) land 1 = 1 then 1. -. xl else xl in
      let xl = if xl = 0. then 0.0001 else xl in
      if zl /. xl < 1. then (match zm with 0 | 3 -> 0. | 2 | 5 -> 1. | _ -> 2.)
      else match zm with 0 | 3 -> 2. | 2 | 5 -> 0. | _ -> 1.

(* §17.7: the fractional part, taken into [0, 1) for negative values *)
let frac a =
  let f = a -. Float.trunc a in
  if f < 0. then f +. 1. else f

let brick (size : Vec.t) mortar (q : Vec.t) =
  let m = mortar +. Precision.epsilon in
  let x = q.x +. m and y = q.y +. m and z = q.z +. m in
  let w = size.x and h = size.y and d = size.z in
  if frac (y /. h) <= mortar /. h then 0.
  else
    let odd = frac (y /. (2. *. h)) > 0.5 in
    if (not odd) && frac (x /. w) <= mortar /. w then 0.
    else if odd && frac ((x /. w) +. 0.5) <= mortar /. w then 0.
    else if odd && frac (z /. d) <= mortar /. d then 0.
    else if (not odd) && frac ((z /. d) +. 0.5) <= mortar /. d then 0.
    else 1.

(* ---------------------------------------------------------------------------------------------- *)
(* Tilings of the XZ plane by cells: square, triangular; and the cube's six pyramids *)

let sqrt3_2 = 0.86602540378443864676372317075294
let sqrt3 = 1.7320508075688772935274463415059
let sqrt2 = 1.4142135623730950488016887242097
let sqrt2_2 = 0.70710678118654752440084436210485

(* 0…3 by the parities of the unit cell's x and z *)
let square (q : Vec.t) =
  let odd_x = c_int (floor q.x) land 1 = 1 and odd_z = c_int (floor q.z) land 1 = 1 in
  if odd_x then if odd_z then 2. else 3. else if odd_z then 1. else 0.

(* 0…5: six triangles around each vertex of a triangular tiling, found in a 3 × √3 rectangle
   folded onto its lower half *)
let triangular (q : Vec.t) =
  let x = q.x and z = q.z in
  let xs = x -. (3.0 *. floor (x /. 3.0)) and zs = z -. (sqrt3 *. floor (z /. sqrt3)) in
  let a = c_int (floor xs) in
  let xs = xs -. float_of_int a in
  let upper = not (zs < sqrt3_2) in
  let zs = if upper then sqrt3 -. zs else zs in
  let k = 1.0 -. xs in
  let answer =
    if xs <> 0.0 && k <> 0.0 then
      let slop1 = zs /. xs and slop2 = zs /. k in
      match (if slop1 < sqrt3 then 1 else 0) + if slop2 < sqrt3 then 2 else 0 with
      | 3 -> 0.0
      | 2 -> 1.0
      | 1 -> 3.0
      | _ -> 0.0 (* the apex of a triangle exactly: POV-Ray leaves the value unset *)
    else 1.0
  in
  let answer =
    if c_int answer land 1 = 1 then Float.rem (answer +. (2.0 *. float_of_int a)) 6.0
    else Float.rem (6.0 +. answer -. (2.0 *. float_of_int a)) 6.0
  in
  if upper then 5.0 -. answer else answer

(* 0…5: the face of the unit cube the point's direction from the origin goes through *)
let cubic (q : Vec.t) =
  let x = q.x and y = q.y and z = q.z in
  let ax = Float.abs x and ay = Float.abs y and az = Float.abs z in
  if x >= 0. && x >= ay && x >= az then 0.
  else if y >= 0. && y >= ax && y >= az then 1.
  else if z >= 0. && z >= ax && z >= ay then 2.
  else if x < 0. && x <= -.ay && x <= -.az then 3.
  else if y < 0. && y <= -.ax && y <= -.az then 4.
  else 5.

(* ---------------------------------------------------------------------------------------------- *)
(* Noise patterns *)

(* agate: a sine of the turbulence and z, raised to 0.77 *)
let agate scale warps gen (q : Vec.t) =
  let turb = match Warp.classic_turb warps with Some t -> t | None -> default_turb in
  let turb_val = scale *. Noise.turbulence turb gen q in
  let noise = 0.5 *. (cycloidal ((1.3 *. turb_val) +. (1.1 *. q.z)) +. 1.0) in
  if noise < 0.0 then 0.0 else Float.pow (fmin 1.0 noise) 0.77

(* granite: six octaves of the folded noise at 4 times the point *)
let granite gen (q : Vec.t) =
  let noise = ref 0.0 and freq = ref 1.0 in
  for _ = 0 to 5 do
    let f = !freq in
    let tv2 = Vec.make (q.x *. 4.0 *. f) (q.y *. 4.0 *. f) (q.z *. 4.0 *. f) in
    let temp =
      if gen = 1 then Float.abs (0.5 -. Noise.noise gen tv2)
      else
        let t = Float.abs (1.0 -. (2.0 *. Noise.noise gen tv2)) in
        if t > 0.5 then 0.5 else t
    in
    noise := !noise +. (temp /. f);
    freq := f *. 2.0
  done;
  !noise

(* one octave of wrinkles: the noise, stretched and clipped to [0, 1] by the newer generators *)
let[@inline] wrinkle_octave gen p =
  if gen > 1 then fmin (fmax ((Noise.noise gen p *. 2.0) -. 0.5) 0.0) 1.0 else Noise.noise gen p

(* wrinkles: ten octaves, each at twice the frequency and half the weight of the last *)
let wrinkles gen (q : Vec.t) =
  let value = ref (wrinkle_octave gen q) and lambda = ref 2.0 and omega = ref 0.5 in
  for _ = 1 to 9 do
    let l = !lambda in
    value := !value +. (!omega *. wrinkle_octave gen (Vec.make (q.x *. l) (q.y *. l) (q.z *. l)));
    lambda := l *. 2.0;
    omega := !omega *. 0.5
  done;
  !value /. 2.0

(* dents: the cube of the noise *)
let dents gen q =
  let n = Noise.noise gen q in
  n *. n *. n

(* marble: x plus the classic turbulence, which marble applies itself *)
let marble warps gen (q : Vec.t) =
  match Warp.classic_turb warps with
  | Some t -> q.x +. (t.turbulence.x *. Noise.turbulence t gen q)
  | None -> q.x +. 0.0

(* wood: the distance from the z axis of x and y pushed by the vector turbulence *)
let wood warps (q : Vec.t) =
  let px = ref 0.0 and py = ref 0.0 in
  (match Warp.classic_turb warps with
  | Some t ->
      let w = Noise.dturbulence t q in
      px := cycloidal ((q.x +. w.x) *. t.turbulence.x);
      py := cycloidal ((q.y +. w.y) *. t.turbulence.y)
  | None -> ());
  let px = !px +. q.x and py = !py +. q.y in
  sqrt ((px *. px) +. (py *. py) +. (0.0 *. 0.0))

(* cells: a random value per unit cube *)
let cells (q : Vec.t) =
  let cx = c_int (floor (q.x +. Precision.epsilon))
  and cy = c_int (floor (q.y +. Precision.epsilon))
  and cz = c_int (floor (q.z +. Precision.epsilon)) in
  fmin (Noise.random_double (Noise.hash3d cx cy cz)) 1.0

(* ---------------------------------------------------------------------------------------------- *)
(* Shapes of space *)

(* leopard: the square of the mean of the coordinates' sines *)
let leopard (q : Vec.t) =
  let t1 = sin q.x and t2 = sin q.y and t3 = sin q.z in
  let v = (t1 +. t2 +. t3) /. 3.0 in
  v *. v

(* 0-1, 0-1, … with the distance from the origin *)
let onion (q : Vec.t) = Float.rem (sqrt ((q.x *. q.x) +. (q.y *. q.y) +. (q.z *. q.z))) 1.0

(* the angle around the y axis from −z, in turns, plus a quarter turn; 0.25 on the axis *)
let radial (q : Vec.t) =
  if Float.abs q.x < 0.001 && Float.abs q.z < 0.001 then 0.25
  else 0.25 +. ((Float.atan2 q.x q.z +. Float.pi) /. two_pi)

let planar (q : Vec.t) = clip_density (Float.abs q.y)
let boxed (q : Vec.t) = clip_density (fmax (Float.abs q.x) (fmax (Float.abs q.y) (Float.abs q.z)))
let spherical (q : Vec.t) = clip_density (sqrt ((q.x *. q.x) +. (q.y *. q.y) +. (q.z *. q.z)))
let cylindrical (q : Vec.t) = clip_density (sqrt ((q.x *. q.x) +. (q.z *. q.z)))

(* quilt_cubic: a cubic Bézier from 0 to 1 with control points [c0] and [c1], over √(3/4) *)
let quilt_cubic t c0 c1 =
  let it = 1. -. t in
  let itsqrd = it *. it and tsqrd = t *. t in
  let tcubed = t *. tsqrd in
  (tcubed +. (3.0 *. t *. itsqrd *. c0) +. (3.0 *. tsqrd *. it *. c1)) *. 1.154700538

(* quilted: the offset from the centre of the unit cube, scaled by the cubic of its length *)
let quilted c0 c1 (q : Vec.t) =
  let vx = q.x -. pov_floor q.x -. 0.5 and vy = q.y -. pov_floor q.y -. 0.5 and vz = q.z -. pov_floor q.z -. 0.5 in
  let t = quilt_cubic (sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz))) c0 c1 in
  (Float.abs (vx *. t) +. Float.abs (vy *. t) +. Float.abs (vz *. t)) /. 3.0

(* the classic turbulence of a spiral: its x amount times the scalar turbulence, or 0 *)
let spiral_turb warps gen q =
  match Warp.classic_turb warps with Some t -> t.turbulence.x *. Noise.turbulence t gen q | None -> 0.0

(* the angle around the z axis, 0…2π, as the spirals measure it *)
let spiral_angle x y rad =
  if rad = 0.0 then 0.0 else if x < 0.0 then (3.0 *. half_pi) -. asin (y /. rad) else half_pi +. asin (y /. rad)

let spiral1 arms warps gen (q : Vec.t) =
  let turb_val = spiral_turb warps gen q in
  let rad = sqrt ((q.x *. q.x) +. (q.y *. q.y)) in
  let phi = spiral_angle q.x q.y rad in
  q.z +. rad +. (float_of_int arms *. phi /. two_pi) +. turb_val

let spiral2 arms warps gen (q : Vec.t) =
  let turb_val = spiral_turb warps gen q in
  let rad = sqrt ((q.x *. q.x) +. (q.y *. q.y)) in
  let phi = spiral_angle q.x q.y rad in
  let turb_val = triangle_wave (q.z +. rad +. (float_of_int arms *. phi /. two_pi) +. turb_val) in
  triangle_wave rad +. turb_val

(* ---------------------------------------------------------------------------------------------- *)
(* waves and ripples: number_of_waves wave sources (Initialize_Waves, texture.cpp; 10 by default) *)

(* the distance to a source, 1 at the source itself *)
let[@inline] source_distance (q : Vec.t) (s : Vec.t) =
  let dx = q.x -. s.x and dy = q.y -. s.y and dz = q.z -. s.z in
  let l = sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
  if l = 0.0 then 1.0 else l

let waves number_of_waves frequency phase q =
  let sources = Noise.wave_sources number_of_waves and freqs = Noise.wave_frequencies number_of_waves in
  let scalar = ref 0.0 in
  for i = 0 to number_of_waves - 1 do
    let index = (source_distance q sources.(i) *. frequency *. freqs.(i)) +. phase in
    scalar := !scalar +. (cycloidal index /. freqs.(i))
  done;
  0.2 *. (2.5 +. (!scalar /. float_of_int number_of_waves))

let ripples number_of_waves frequency phase q =
  let sources = Noise.wave_sources number_of_waves in
  let scalar = ref 0.0 in
  for i = 0 to number_of_waves - 1 do
    scalar := !scalar +. cycloidal ((source_distance q sources.(i) *. frequency) +. phase)
  done;
  0.5 *. (1.0 +. (!scalar /. float_of_int number_of_waves))

(* ---------------------------------------------------------------------------------------------- *)
(* crackle: distances to the nearest random points, one point per unit cube *)

(* The 81 cubes searched around the point's own, as offsets in −2…2 with at most one of them ±2,
   in the order POV-Ray's table lists them (InitialiseCrackleCubeTable): x, then y, then z *)
let crackle_cubes =
  let t = Array.make (81 * 3) 0 and n = ref 0 in
  for dx = -2 to 2 do
    for dy = -2 to 2 do
      for dz = -2 to 2 do
        let twos = (if abs dx = 2 then 1 else 0) + (if abs dy = 2 then 1 else 0) + if abs dz = 2 then 1 else 0 in
        if twos <= 1 then begin
          t.(!n) <- dx;
          t.(!n + 1) <- dy;
          t.(!n + 2) <- dz;
          n := !n + 3
        end
      done
    done
  done;
  t

(* The random point of the cube with corner <cx,cy,cz> (IntPickInCube): the cube's hash picks
   three consecutive values of PatternRands *)
let[@inline] cube_seed cx cy cz = Noise.hash3d (cx land 0xFFF) (cy land 0xFFF) (cz land 0xFFF)

(* The distance under the metric: squared Euclidean (2), Manhattan (1), else Σ|d|^m *)
let[@inline] crackle_distance metric dx dy dz =
  if metric = 2. then (dx *. dx) +. (dy *. dy) +. (dz *. dz)
  else if metric = 1. then Float.abs dx +. Float.abs dy +. Float.abs dz
  else Float.pow (Float.abs dx) metric +. Float.pow (Float.abs dy) metric +. Float.pow (Float.abs dz) metric

(* the distance from [q] to the random point of the [i]-th cube around <flox,floy,floz> *)
let[@inline] crackle_distance_to metric flox floy floz i (q : Vec.t) =
  let cx = flox + crackle_cubes.(3 * i)
  and cy = floy + crackle_cubes.((3 * i) + 1)
  and cz = floz + crackle_cubes.((3 * i) + 2) in
  let seed = cube_seed cx cy cz in
  let px = float_of_int cx +. Noise.random_double seed
  and py = float_of_int cy +. Noise.random_double (seed + 1)
  and pz = float_of_int cz +. Noise.random_double (seed + 2) in
  crackle_distance metric (px -. q.x) (py -. q.y) (pz -. q.z)

let crackle (form : Vec.t) metric offset solid gen (q : Vec.t) =
  let flox = c_int (floor (q.x -. Precision.epsilon))
  and floy = c_int (floor (q.y -. Precision.epsilon))
  and floz = c_int (floor (q.z -. Precision.epsilon)) in
  (* the three smallest distances, kept sorted, and which cube has the smallest; the first three
     are sorted as POV-Ray does, whose ties then decide the cube *)
  let minsum = ref (crackle_distance_to metric flox floy floz 0 q)
  and minsum2 = ref (crackle_distance_to metric flox floy floz 1 q)
  and minsum3 = ref (crackle_distance_to metric flox floy floz 2 q) in
  let nearest = ref 0 in
  if !minsum2 < !minsum then begin
    let tf = !minsum in
    minsum := !minsum2;
    minsum2 := tf;
    nearest := 1
  end;
  if !minsum3 < !minsum then begin
    let tf = !minsum in
    minsum := !minsum3;
    minsum3 := tf;
    nearest := 2
  end;
  if !minsum3 < !minsum2 then begin
    let tf = !minsum2 in
    minsum2 := !minsum3;
    minsum3 := tf
  end;
  for i = 3 to 80 do
    let sum = crackle_distance_to metric flox floy floz i q in
    if sum < !minsum then begin
      minsum3 := !minsum2;
      minsum2 := !minsum;
      minsum := sum;
      nearest := i
    end
    else if sum < !minsum2 then begin
      minsum3 := !minsum2;
      minsum2 := sum
    end
    else if sum < !minsum3 then minsum3 := sum
  done;
  if offset <> 0. then begin
    let o = if metric = 2. then offset *. offset else if metric = 1. then offset else Float.pow offset metric in
    minsum := !minsum +. o;
    minsum2 := !minsum2 +. o;
    minsum3 := !minsum3 +. o
  end;
  let tf =
    if solid then
      let i = !nearest in
      let cx = flox + crackle_cubes.(3 * i)
      and cy = floy + crackle_cubes.((3 * i) + 1)
      and cz = floz + crackle_cubes.((3 * i) + 2) in
      let seed = cube_seed cx cy cz in
      Noise.noise gen
        (Vec.make
           (float_of_int cx +. Noise.random_double seed)
           (float_of_int cy +. Noise.random_double (seed + 1))
           (float_of_int cz +. Noise.random_double (seed + 2)))
    else if metric = 2. then (form.x *. sqrt !minsum) +. (form.y *. sqrt !minsum2) +. (form.z *. sqrt !minsum3)
    else if metric = 1. then (form.x *. !minsum) +. (form.y *. !minsum2) +. (form.z *. !minsum3)
    else
      let e = 1.0 /. metric in
      (form.x *. Float.pow !minsum e) +. (form.y *. Float.pow !minsum2 e) +. (form.z *. Float.pow !minsum3 e)
  in
  fmax (fmin tf 1.) 0.

(* ---------------------------------------------------------------------------------------------- *)
(* Fractals: mandel, julia (exponents 2 to 33) and magnet (pattern.cpp) *)

let max_exponent = 33

(* Pascal's triangle up to row 33 with the signs of i^k: row m's entry k (k ≥ 1) is negated when
   bit 1 of k is set (InitializeBinomialCoefficients); row m starts at m(m+1)/2 *)
let binomial =
  let t = Array.make ((max_exponent + 1) * (max_exponent + 2) / 2) 0 in
  t.(0) <- 1;
  for n = 1 to max_exponent do
    let row = n * (n + 1) / 2 and above = (n - 1) * n / 2 in
    t.(row) <- 1;
    for k = 1 to n - 1 do
      t.(row + k) <- t.(above + k - 1) + t.(above + k)
    done;
    t.(row + n) <- 1
  done;
  for m = 1 to max_exponent do
    let row = m * (m + 1) / 2 in
    for k = 1 to m do
      if k land 2 <> 0 then t.(row + k) <- -t.(row + k)
    done
  done;
  t

(* fractal_exterior_color: the value where the orbit escaped after [iters] steps at (a, b) *)
let exterior (f : Scene.fractal) iters a b =
  match f.exterior_type with
  | 0 -> f.efactor
  | 1 -> float_of_int iters /. float_of_int (f.iterations land 0xFFFFFFFF)
  | 2 -> a *. f.efactor
  | 3 -> b *. f.efactor
  | 4 -> a *. a *. f.efactor
  | 5 -> b *. b *. f.efactor
  | 6 -> sqrt ((a *. a) +. (b *. b)) *. f.efactor
  | 7 ->
      (* iters mod (unsigned) efactor, over efactor: 0 … (n−1)/n *)
      let m = Int64.to_int (Int64.of_float f.efactor) land 0xFFFFFFFF in
      if m = 0 then 0. else float_of_int (iters mod m) /. f.efactor
  | 8 ->
      let m = Int64.to_int (Int64.of_float (1. +. f.efactor)) land 0xFFFFFFFF in
      if m = 0 then 0. else float_of_int (iters mod m) /. f.efactor
  | _ -> 0.

(* fractal_interior_color: the value where the orbit stayed; [mindist2] is its least |z|² *)
let interior (f : Scene.fractal) a b mindist2 =
  match f.interior_type with
  | 0 -> f.ifactor
  | 1 -> sqrt mindist2 *. f.ifactor
  | 2 -> a *. f.ifactor
  | 3 -> b *. f.ifactor
  | 4 -> a *. a *. f.ifactor
  | 5 -> b *. b *. f.ifactor
  | 6 -> (a *. a) +. (b *. b *. f.ifactor) (* POV-Ray's precedence: only b² is scaled *)
  | _ -> 0.

(* z ← z^e + c from z = the point, for e = 2, 3, 4 with POV-Ray's expanded products, and for
   larger e by the binomial expansion with pow (mandel*_pattern, julia*_pattern); the mandel sets
   take c = the point itself *)
let power_set (f : Scene.fractal) e cr ci (q : Vec.t) =
  let a = ref q.x and b = ref q.y in
  let a2 = ref (!a *. !a) and b2 = ref (!b *. !b) in
  let mindist2 = ref (!a2 +. !b2) in
  let it_max = f.iterations in
  let col = ref 0 and escaped = ref false and cf = ref 0.0 in
  let coeff = (e + 1) * e / 2 in
  while (not !escaped) && !col < it_max do
    (match e with
    | 2 ->
        b := (2.0 *. !a *. !b) +. ci;
        a := !a2 -. !b2 +. cr
    | 3 ->
        b := (3.0 *. !a2 *. !b) -. (!b2 *. !b) +. ci;
        a := (!a2 *. !a) -. (3.0 *. !a *. !b2) +. cr
    | 4 ->
        b := (4.0 *. ((!a2 *. !a *. !b) -. (!a *. !b2 *. !b))) +. ci;
        a := (!a2 *. !a2) -. (6.0 *. !a2 *. !b2) +. (!b2 *. !b2) +. cr
    | _ ->
        let x = !a and y = !b in
        let new_a = ref (Float.pow x (float_of_int e)) in
        let k = ref 2 in
        while !k <= e do
          let c = float_of_int binomial.(coeff + !k) in
          new_a := !new_a +. (c *. Float.pow x (float_of_int (e - !k)) *. Float.pow y (float_of_int !k));
          k := !k + 2
        done;
        let new_b = ref 0. and l = ref 1 in
        while !l <= e do
          let c = float_of_int binomial.(coeff + !l) in
          new_b := !new_b +. (c *. Float.pow x (float_of_int (e - !l)) *. Float.pow y (float_of_int !l));
          l := !l + 2
        done;
        a := !new_a +. cr;
        b := !new_b +. ci);
    a2 := !a *. !a;
    b2 := !b *. !b;
    let dist2 = !a2 +. !b2 in
    if dist2 < !mindist2 then mindist2 := dist2;
    if dist2 > 4.0 then begin
      cf := exterior f !col !a !b;
      escaped := true
    end
    else incr col
  done;
  if !col = it_max then interior f !a !b !mindist2 else !cf

(* the exponent a mandel or julia pattern is computed with: 2 to 33, any other stored value
   meaning 2 (Parse_Pattern's warning) *)
let power_of (f : Scene.fractal) = if f.exponent >= 2 && f.exponent <= max_exponent then f.exponent else 2

(* The magnet formulas: z ← ((z² + c − 1)/(2z + c − 2))² (type 1) or the cubic form of type 2,
   from z = 0 with c = the point (mandel) or from z = the point with c given (julia); the orbit
   escapes beyond |z|² = 10000 or when it comes within 0.01 of 1 *)
let magnet (f : Scene.fractal) kind mandel cr ci (q : Vec.t) =
  let x = q.x and y = q.y in
  let cr = if mandel then x else cr and ci = if mandel then y else ci in
  let a = ref (if mandel then 0. else x) and b = ref (if mandel then 0. else y) in
  let a2 = ref (!a *. !a) and b2 = ref (!b *. !b) in
  let mindist2 = ref (if mandel then 10000. else !a2 +. !b2) in
  let c1r = cr -. 1. and c2r = cr -. 2. in
  let c1c2r = (c1r *. c2r) -. (ci *. ci) and c1c2i = (c1r +. c2r) *. ci in
  let it_max = f.iterations in
  let col = ref 0 and escaped = ref false and cf = ref 0.0 in
  while (not !escaped) && !col < it_max do
    let a0 = !a and b0 = !b and a20 = !a2 and b20 = !b2 in
    let tmp1r =
      if kind = 1 then a20 -. b20 +. cr -. 1.
      else (a20 *. a0) -. (3. *. a0 *. b20) +. (3. *. ((a0 *. c1r) -. (b0 *. ci))) +. c1c2r
    and tmp1i =
      if kind = 1 then (2. *. a0 *. b0) +. ci
      else (3. *. a20 *. b0) -. (b20 *. b0) +. (3. *. ((a0 *. ci) +. (b0 *. c1r))) +. c1c2i
    and tmp2r =
      if kind = 1 then (2. *. a0) +. cr -. 2.
      else (3. *. (a20 -. b20)) +. (3. *. ((a0 *. c2r) -. (b0 *. ci))) +. c1c2r +. 1.
    and tmp2i =
      if kind = 1 then (2. *. b0) +. ci else (6. *. a0 *. b0) +. (3. *. ((a0 *. ci) +. (b0 *. c2r))) +. c1c2i
    in
    let tmp = (tmp2r *. tmp2r) +. (tmp2i *. tmp2i) in
    let na = ((tmp1r *. tmp2r) +. (tmp1i *. tmp2i)) /. tmp in
    let nb = ((tmp1i *. tmp2r) -. (tmp1r *. tmp2i)) /. tmp in
    let nb2 = nb *. nb in
    b := 2. *. na *. nb;
    a := (na *. na) -. nb2;
    a2 := !a *. !a;
    b2 := !b *. !b;
    let dist2 = !a2 +. !b2 in
    if dist2 < !mindist2 then mindist2 := dist2;
    let d = !a -. 1. in
    if dist2 > 10000.0 || (d *. d) +. !b2 < 1. /. 10000.0 then begin
      cf := exterior f !col !a !b;
      escaped := true
    end
    else incr col
  done;
  if !col = it_max then interior f !a !b !mindist2 else !cf

let fractal (f : Scene.fractal) (q : Vec.t) =
  match f.fkind with
  | Mandel -> power_set f (power_of f) q.x q.y q
  | Julia (cr, ci) -> power_set f (power_of f) cr ci q
  | Magnet_mandel kind -> magnet f kind true 0. 0. q
  | Magnet_julia (kind, (cr, ci)) -> magnet f kind false cr ci q

(* ---------------------------------------------------------------------------------------------- *)
(* Patterns of the surface: slope and aoi *)

let[@inline] component (v : Vec.t) axis = match axis with 0 -> v.x | 1 -> v.y | _ -> v.z

(* slope: the angle of the normal to the slope vector, taken to [0, 1] and shaped by the slope's
   range, mixed with the height along the altitude vector; wrapped into [0, 1), exactly 1 kept
   just below 1. [point_at] aims at the slope vector from the point: POV-Ray takes the
   intersection point itself, which [hit] does not carry, and this takes the pattern-space point
   [q] (the same when the pattern is not transformed or warped). *)
let slope (s : Scene.slope) (hit : hit) (q : Vec.t) =
  if hit == no_hit then 0.0
  else
    let value1 =
      if s.point_at then Vec.dot hit.normal (Vec.normalize (Vec.sub s.slope_vector q))
      else if s.slope_base > 0 then component hit.normal (s.slope_base - 1)
      else if s.slope_base < 0 then -.component hit.normal (-s.slope_base - 1)
      else Vec.dot hit.normal s.slope_vector
    in
    let value1 = if value1 > 1.0 then 1.0 else if value1 < -1.0 then -1.0 else value1 in
    let value1 = asin value1 /. Float.pi *. 2. in
    let value1 = (value1 +. 1.0) *. 0.5 in
    let lo, range = s.slope_mod in
    let value1 = if 0.0 <> range then (value1 -. lo) /. range else value1 in
    if s.altit_len = 0. then
      if value1 = 1.0 then value1 -. Precision.epsilon
      else if value1 < 0.0 then 1.0 +. Float.rem value1 1.0
      else Float.rem value1 1.0
    else
      let value2 =
        if s.altit_base > 0 then component q (s.altit_base - 1)
        else if s.altit_base < 0 then -.component q (-s.altit_base - 1)
        else Vec.dot q s.altit_vector
      in
      let alo, arange = s.altit_mod in
      let value2 = if 0.0 <> arange then (value2 -. alo) /. arange else value2 in
      let value = (s.slope_len *. value1) +. (s.altit_len *. value2) in
      if value -. 1.0 < Precision.epsilon && value >= 1.0 then value -. Precision.epsilon
      else if value < 0.0 then 1.0 +. Float.rem value 1.0
      else Float.rem value 1.0

(* the angle between the surface normal and the ray, over π *)
let aoi (hit : hit) =
  if hit == no_hit then 0.0
  else
    let c = Vec.dot (Vec.normalize hit.normal) (Vec.normalize hit.dir) in
    let c = if c < -1.0 then -1.0 else if c > 1.0 then 1.0 else c in
    acos c /. Float.pi

(* ---------------------------------------------------------------------------------------------- *)
(* tiling 1…27: classical tilings of the XZ plane (J. Grimbert's, pattern.cpp). With one kind of
   tile the value is 1 on its edge and falls to 0 inside; with several kinds each has its own
   band of values. Each folds the point into a fundamental cell by translations and mirrors. *)

module Tiling = struct
  (* a point of the XZ plane taken through a substitution: an all-float record, so that its fields
     are stored unboxed *)
  type point2 = { mutable px : float; mutable pz : float }

  let sin18 = 0.30901699437494742410229341718282
  let sin36 = 0.58778525229247312916870595463907
  let sin54 = 0.80901699437494742410229341718282
  let sin72 = 0.95105651629515357211643933337938
  let sin108 = sin72
  let sin144 = sin36
  let sin162 = sin18
  let cos18 = sin72
  let cos36 = sin54
  let cos72 = sin18
  let cos108 = -.cos72
  let cos144 = -.cos36
  let cos162 = -.cos18
  let tan18 = 0.32491969623290632615587141221513
  let tan36 = 0.72654252800536088589546675748062
  let tan54 = 1.3763819204711735382072095819109
  let tan72 = 3.0776835371752534025702905760369
  let tan126 = -.tan54
  let tan144 = -.tan36
  let tan162 = -.tan18
  let phi = 1.6180339887498948482045868343656
  let invphi = 0.61803398874989484820458683436564
  let sqrphi = 2.6180339887498948482045868343656
  let invsqrphi = 0.38196601125010515179541316563436
  let tiling_epsilon = 1e-6

  let square (p : Vec.t) =
    let x = Float.abs p.x in
    let x = x -. floor x in
    let x = 2. *. Float.abs (x -. 0.5) in
    let z = Float.abs p.z in
    let z = z -. floor z in
    let z = 2. *. Float.abs (z -. 0.5) in
    fmax x z

  let hexagon (p : Vec.t) =
    let x = ref (p.x +. 0.5) and z = ref p.z in
    x := !x -. (3.0 *. floor (!x /. 3.0));
    z := !z -. (sqrt3 *. floor (!z /. sqrt3));
    (* [0,3) × [0,√3): fold the upper half, then the right half, onto [0,1.5] × [0,√3/2] *)
    if !z > sqrt3_2 then z := sqrt3 -. !z;
    if !x > 1.5 then begin
      x := !x -. 1.5;
      z := sqrt3_2 -. !z
    end;
    (* the lower left corner belongs to another hexagon *)
    if (sqrt3 *. !x) +. !z < sqrt3_2 then begin
      x := 0.5 -. !x;
      z := sqrt3_2 -. !z
    end;
    if !x > 1.0 then x := 2.0 -. !x;
    let dist1 = 1.0 -. (!z /. sqrt3_2) in
    let dist2 = 1.0 -. (((sqrt3 *. !x) +. !z -. sqrt3_2) /. sqrt3) in
    fmax 0.0 (fmin 1.0 (fmax dist1 dist2))

  let triangle (p : Vec.t) =
    let x = ref p.x and z = ref p.z and delta = ref 0 in
    x := !x -. floor !x;
    z := !z -. (sqrt3 *. floor (!z /. sqrt3));
    if !z > sqrt3_2 then begin
      z := sqrt3 -. !z;
      delta := 1 - !delta
    end;
    if !x > 0.5 then x := 1.0 -. !x;
    if !x <> 0.0 then begin
      if !z /. !x > sqrt3 then begin
        z := sqrt3_2 -. !z;
        x := 0.5 -. !x;
        delta := 1 - !delta
      end
    end
    else begin
      z := sqrt3_2 -. !z;
      x := 0.5
    end;
    let dist1 = 1.0 -. (!z *. 2. *. sqrt3) in
    let dist2 = 1.0 -. (((sqrt3 *. !x) -. !z) *. sqrt3) in
    (float_of_int !delta /. 2.0) +. (0.5 *. fmax dist1 dist2)

  (* the lozenge of tilings 4 and 5 in its cell [0,0.75] × [0,√3/4] *)
  let[@inline] lozenge_cell x z =
    let x = ref x and z = ref z in
    if 2.0 *. !z > sqrt3_2 then begin
      z := sqrt3_2 -. !z;
      x := 1.5 -. !x
    end;
    if !x > 0.75 then x := !x -. 1.0;
    if !x <> 0.0 then
      if !z /. !x > sqrt3 then begin
        z := sqrt3_2 -. !z;
        x := 0.5 -. !x
      end;
    let dist1 = 1.0 -. (!z *. 4.0 *. sqrt3 /. 3.0) in
    let dist2 = 1.0 -. (Float.abs ((sqrt3 *. !x) -. !z) *. sqrt3 *. 2.0 /. 3.0) in
    fmax dist1 dist2

  let lozenge (p : Vec.t) =
    let x = ref p.x and z = ref p.z in
    x := !x -. floor !x;
    z := !z -. (sqrt3 *. floor (!z /. sqrt3));
    if !z > sqrt3_2 then begin
      z := !z -. sqrt3_2;
      x := !x +. 0.5
    end;
    lozenge_cell !x !z

  let rhombus (p : Vec.t) =
    let x = ref (p.x +. 0.5) and z = ref p.z and delta = ref 0 in
    x := !x -. (3.0 *. floor (!x /. 3.0));
    z := !z -. (sqrt3 *. floor (!z /. sqrt3));
    if !z > sqrt3_2 then begin
      z := sqrt3 -. !z;
      delta := 2 - !delta
    end;
    if !x > 1.5 then begin
      x := !x -. 1.5;
      z := sqrt3_2 -. !z;
      delta := 2 - !delta
    end;
    (* [0,1.5] × [0,√3/2]: part of a horizontal rhombus, half a vertical one, part of another *)
    if !x < 0.5 then begin
      x := 1.0 -. !x;
      delta := 2 - !delta
    end;
    x := !x -. 0.5;
    (* the vertical rhombus is turned onto the horizontal one on its right *)
    if !x = 0.0 || !z /. !x > sqrt3 then begin
      let dist1 = (!x /. 2.0) +. (!z *. sqrt3_2) and dist2 = (!z /. 2.0) -. (!x *. sqrt3_2) in
      z := dist2;
      x := dist1;
      delta := 1
    end;
    let answer = lozenge_cell !x !z /. 3.0 in
    let answer = answer +. (float_of_int !delta /. 3.0) in
    fmax 0.0 (fmin 1.0 answer)

  let rectangle (p : Vec.t) =
    let x = ref (p.x -. (4.0 *. floor (p.x /. 4.0))) and z = ref (p.z -. (4.0 *. floor (p.z /. 4.0))) in
    let delta = ref 1.0 in
    (match c_int !x + (c_int !z * 4) with
    | 0 | 4 -> z := !z -. 1.0
    | 1 | 2 ->
        x := !x -. 2.0;
        delta := 0.0
    | 3 -> x := !x -. 3.0
    | 5 | 9 ->
        x := !x -. 1.0;
        z := !z -. 2.0
    | 6 | 7 ->
        x := !x -. 3.0;
        z := !z -. 1.0;
        delta := 0.0
    | 8 ->
        z := !z -. 2.0;
        delta := 0.0
    | 10 | 14 ->
        x := !x -. 2.0;
        z := !z -. 3.0
    | 11 ->
        x := !x -. 4.0;
        z := !z -. 2.0;
        delta := 0.0
    | 12 | 13 ->
        x := !x -. 1.0;
        z := !z -. 3.0;
        delta := 0.0
    | 15 ->
        x := !x -. 3.0;
        z := !z -. 4.0
    | _ -> ());
    let x, z =
      if !delta = 1.0 then (2. *. Float.abs (!x -. 0.5), 2. *. (fmax (Float.abs !z) 0.5 -. 0.5))
      else (2. *. (fmax (Float.abs !x) 0.5 -. 0.5), 2. *. Float.abs (!z -. 0.5))
    in
    Float.abs ((fmax x z /. 2.0) +. (!delta /. 2.))

  let octa_square (p : Vec.t) =
    let period = sqrt2 +. 1.0 in
    let z = p.z -. (period *. floor (p.z /. period)) in
    let z = Float.abs (z -. (sqrt2_2 +. 0.5)) in
    let x = p.x -. (period *. floor (p.x /. period)) in
    let x = Float.abs (x -. (sqrt2_2 +. 0.5)) in
    let x, z = if z > x then (z, x) else (x, z) in
    if x +. z < sqrt2_2 then (x +. z) /. sqrt2
    else
      let dist1 = 1.0 -. z and dist2 = (sqrt2 +. sqrt2_2 -. (x +. z)) /. sqrt2 in
      fmax 0.500000000001 (fmax dist1 dist2)

  let square_triangle (p : Vec.t) =
    let x = ref p.x and z = ref p.z and delta = ref 0 in
    x := !x -. floor !x;
    z := !z -. ((2.0 +. sqrt3) *. floor (!z /. (sqrt3 +. 2.0)));
    if !z > sqrt3_2 +. 1.0 then begin
      z := !z -. (sqrt3_2 +. 1.0);
      x := !x +. if !x > 0.5 then -0.5 else 0.5
    end;
    if !x > 0.5 then x := 1.0 -. !x;
    z := !z -. 1.0;
    if !z > 0.0 then begin
      (* a triangle *)
      if !x <> 0.0 then begin
        if !z /. !x > sqrt3 then begin
          z := sqrt3_2 -. !z;
          x := 0.5 -. !x;
          delta := 1 - !delta
        end
      end
      else begin
        z := sqrt3_2 -. !z;
        x := 0.5;
        delta := 1 - !delta
      end;
      let dist1 = 1.0 -. (2. *. !z *. sqrt3) and dist2 = 1.0 -. (((sqrt3 *. !x) -. !z) *. sqrt3) in
      (float_of_int !delta +. fmax dist1 dist2) /. 3.0
    end
    else begin
      (* a square *)
      if !z < -0.5 then z := -1.0 -. !z;
      if !x > 0.5 then x := 1.0 -. !x;
      let dist1 = fmin (2. +. (2. *. sqrt3 *. Float.abs !x)) 3.0 in
      let dist2 = fmin (2. +. (2. *. sqrt3 *. Float.abs !z)) 3.0 in
      (5.0000001 -. fmin dist1 dist2) /. 3.0
    end

  let hexa_triangle (p : Vec.t) =
    let x = ref (p.x +. 0.5) and z = ref p.z and delta = ref 0 in
    x := !x -. (2.0 *. floor (!x /. 2.0));
    z := !z -. (2.0 *. sqrt3 *. floor (!z /. (sqrt3 *. 2.0)));
    if !z > sqrt3 then begin
      z := !z -. sqrt3;
      x := !x +. if !x < 1.0 then 1.0 else -1.0
    end;
    if !z > sqrt3_2 then begin
      z := sqrt3 -. !z;
      delta := 1 - !delta
    end;
    if !x > 1.0 then x := 2.0 -. !x;
    (* [0,1] × [0,√3/2]: a triangle in the lower left corner, the hexagon's centre upper right *)
    if (sqrt3 *. !x) +. !z < sqrt3_2 then
      let dist1 = 1.0 -. (!z *. 2. *. sqrt3) in
      let dist2 = 1.0 +. (((sqrt3 *. !x) +. !z -. sqrt3_2) *. sqrt3) in
      (float_of_int !delta +. fmax dist1 dist2) /. 3.0
    else
      let dist1 = 2. +. (2. *. (!z *. sqrt3)) in
      let dist2 = 2. +. (2. *. ((sqrt3 *. !x) +. !z -. sqrt3_2) *. sqrt3_2) in
      fmax (5.0 -. fmin dist1 dist2) 2.0000001 /. 3.0

  let square_offset (p : Vec.t) =
    let z = p.z -. (2.0 *. floor (p.z /. 2.0)) in
    let x, z = if z > 1.0 then (p.x +. 0.5, z -. 1.0) else (p.x, z) in
    let x = x -. floor x in
    fmax (2. *. Float.abs (x -. 0.5)) (2. *. Float.abs (z -. 0.5))

  (* a central square and four 2×1 rectangles around it, in the cell [0,3)²: tilings 11, 12 *)
  let[@inline] square_rectangle_cell x z =
    let x = ref x and z = ref z and delta = ref 2.0 in
    (match c_int !x + (c_int !z * 3) with
    | 0 | 3 -> z := !z -. 1.0
    | 1 | 2 ->
        x := !x -. 2.0;
        delta := 1.0
    | 4 ->
        x := !x -. 1.0;
        z := !z -. 1.0;
        delta := 0.0
    | 5 | 8 ->
        x := !x -. 2.0;
        z := !z -. 2.0
    | 6 | 7 ->
        x := !x -. 1.0;
        z := !z -. 2.0;
        delta := 1.0
    | _ -> ());
    if !delta = 1.0 then begin
      x := Float.abs !x;
      x := 2.0 *. (fmax !x 0.5 -. 0.5);
      z := 2.0 *. Float.abs (!z -. 0.5)
    end;
    if !delta = 2.0 then begin
      x := 2.0 *. Float.abs (!x -. 0.5);
      z := Float.abs !z;
      z := 2.0 *. (fmax !z 0.5 -. 0.5)
    end;
    if !delta = 0.0 then begin
      x := 2.0 *. Float.abs (!x -. 0.5);
      z := 2.0 *. Float.abs (!z -. 0.5)
    end;
    (fmax !x !z +. !delta) /. 3.0

  let square_rectangle (p : Vec.t) =
    square_rectangle_cell (p.x -. (3.0 *. floor (p.x /. 3.0))) (p.z -. (3.0 *. floor (p.z /. 3.0)))

  (* the same cell mirrored four times in [0,6)², so the rectangles turn both ways *)
  let rectangle_square (p : Vec.t) =
    let fold a = Float.abs (a -. (6.0 *. floor (a /. 6.0)) -. 3.0) in
    square_rectangle_cell (fold p.x) (fold p.z)

  (* squares at 45°, folded into [0,2]² of √2-scaled space: tilings 13 and 14 *)
  let[@inline] internal_fold a =
    let a = a *. sqrt2 in
    Float.abs (a -. (4.0 *. floor (a /. 4.0)) -. 2.0)

  let square_internal (p : Vec.t) =
    let x = internal_fold p.x and z = internal_fold p.z in
    match c_int x + (c_int z * 2) with
    | 0 ->
        let x = fmax (x -. 0.5) 0.0 *. 2.0 and z = fmax (z -. 0.5) 0.0 *. 2.0 in
        fmax x z /. 3.0
    | 1 ->
        let answer = (2.0 +. (Float.abs (1.5 -. x) *. 2.0)) /. 3.0 in
        if z > 0.5 then fmax answer ((3.0 -. (sqrt2 *. Float.abs (x -. z))) /. 3.0) else answer
    | 2 ->
        let answer = (1.0 +. (Float.abs (1.5 -. z) *. 2.0)) /. 3.0 in
        if x > 0.5 then fmax answer ((2.0 -. (sqrt2 *. Float.abs (x -. z))) /. 3.0) else answer
    | 3 ->
        if x > z then
          fmax ((2.0 +. (Float.abs (1.5 -. x) *. 2.0)) /. 3.0) ((3.0 -. (sqrt2 *. Float.abs (z -. x))) /. 3.0)
        else fmax ((1.0 +. (Float.abs (1.5 -. z) *. 2.0)) /. 3.0) ((2.0 -. (sqrt2 *. Float.abs (x -. z))) /. 3.0)
    | _ -> 0.

  let square_internal_5 (p : Vec.t) =
    let x = p.x *. sqrt2 in
    let x = x -. (4.0 *. floor (x /. 4.0)) -. 2.0 in
    let mir_x = if x < 0. then 1. else 0. in
    let x = Float.abs x in
    let z = p.z *. sqrt2 in
    let z = z -. (4.0 *. floor (z /. 4.0)) -. 2.0 in
    let mir_z = if z < 0. then 2. else 3. in
    let z = Float.abs z in
    match c_int x + (c_int z * 2) with
    | 0 ->
        let x = fmax (x -. 0.5) 0.0 *. 2.0 and z = fmax (z -. 0.5) 0.0 *. 2.0 in
        (4.000001 +. fmax x z) /. 5.0
    | 1 ->
        let answer = Float.abs (1.5 -. x) *. 2.0 in
        let answer = if z > 0.5 then fmax answer (1.0 -. (sqrt2 *. Float.abs (x -. z))) else answer in
        (answer +. mir_x) /. 5.0
    | 2 ->
        let answer = Float.abs (1.5 -. z) *. 2.0 in
        let answer = if x > 0.5 then fmax answer (1.0 -. (sqrt2 *. Float.abs (x -. z))) else answer in
        (answer +. mir_z) /. 5.0
    | 3 ->
        if x > z then (fmax (Float.abs (1.5 -. x) *. 2.0) (1.0 -. (sqrt2 *. Float.abs (z -. x))) +. mir_x) /. 5.0
        else (fmax (Float.abs (1.5 -. z) *. 2.0) (1.0 -. (sqrt2 *. Float.abs (x -. z))) +. mir_z) /. 5.0
    | _ -> 0.

  let square_double (p : Vec.t) =
    let x = ref (p.x -. (5.0 *. floor (p.x /. 5.0))) and z = ref (p.z -. (5.0 *. floor (p.z /. 5.0))) in
    let delta = ref 0.50000001 in
    (* the corner of the cell's tile, and whether it is a small square (delta 0) *)
    let dx, dz, small =
      match c_int !x + (c_int !z * 5) with
      | 0 -> (0.0, 0.0, true)
      | 1 | 2 -> (2.0, 0.0, false)
      | 3 | 4 | 8 | 9 -> (4.0, 1.0, false)
      | 5 | 6 | 10 | 11 -> (1.0, 2.0, false)
      | 7 -> (2.0, 1.0, true)
      | 12 | 13 | 17 | 18 -> (3.0, 3.0, false)
      | 14 -> (4.0, 2.0, true)
      | 15 | 20 -> (0.0, 4.0, false)
      | 16 -> (1.0, 3.0, true)
      | 21 | 22 -> (2.0, 5.0, false)
      | 23 -> (3.0, 4.0, true)
      | 24 | 19 -> (5.0, 4.0, false)
      | _ -> (0.0, 0.0, false)
    in
    x := !x -. dx;
    z := !z -. dz;
    if small then delta := 0.0;
    let x, z =
      if !delta <> 0. then (2. *. (fmax (Float.abs !x) 0.5 -. 0.5), 2. *. (fmax (Float.abs !z) 0.5 -. 0.5))
      else (2. *. Float.abs (!x -. 0.5), 2. *. Float.abs (!z -. 0.5))
    in
    Float.abs ((fmax x z /. 2.0) +. !delta)

  (* one hexagon, squares and triangles in [0, 3+√3) × [0, 2(1+√3)), folded onto
     [0, 1+√3/2]²; [tiles] is 3 (hexagon, square, triangle) or 6 (the orientations apart) *)
  let hexa_square_triangle_n six (p : Vec.t) =
    let x = ref (p.x +. 0.5) and z = ref p.z in
    let mir_x = ref 0 and mir_z = ref 0 and rota = ref 0 in
    x := !x -. ((3.0 +. sqrt3) *. floor (!x /. (3.0 +. sqrt3)));
    z := !z -. (2.0 *. (1.0 +. sqrt3) *. floor (!z /. ((sqrt3 +. 1.0) *. 2.0)));
    if !x > sqrt3_2 +. 1.5 then begin
      x := !x -. (sqrt3_2 +. 1.5);
      z := !z +. if !z < sqrt3 +. 1.0 then sqrt3_2 +. 0.5 else -1. *. (sqrt3_2 +. 0.5)
    end;
    if !z > sqrt3 +. 1.0 then z := !z -. (sqrt3 +. 1.0);
    if !z > 0.5 +. sqrt3_2 then begin
      z := sqrt3 +. 1.0 -. !z;
      mir_z := 1 - !mir_z
    end;
    if !x > 1.0 +. sqrt3_2 then begin
      x := sqrt3 +. 2.0 -. !x;
      mir_x := 1 - !mir_x
    end;
    (* a triangle or a square: turned by 60° about the hexagon's corner into the lower part *)
    if (sqrt3 *. !x) +. !z < sqrt3_2 +. 2.0 && !x < 0.5 +. sqrt3_2 then begin
      z := !z -. (0.5 +. sqrt3_2);
      x := !x -. (1.0 +. sqrt3_2);
      let dist1 = (!x /. 2.0) -. (!z *. sqrt3_2) and dist2 = (!z /. 2.0) +. (!x *. sqrt3_2) in
      z := dist2;
      x := dist1;
      z := !z +. (0.5 +. sqrt3_2);
      x := !x +. (1.0 +. sqrt3_2);
      rota := 1 - !rota;
      if !z < 0. then z := !z *. -1.;
      if !x > 1.0 +. sqrt3_2 then begin
        x := sqrt3 +. 2.0 -. !x;
        mir_x := 1 - !mir_x;
        mir_z := 1 - !mir_z
      end
    end;
    if (not ((sqrt3 *. !x) +. !z < sqrt3_2 +. 2.0)) && not (!z < 0.5) then begin
      (* the hexagon *)
      let z = Float.abs (!z -. 0.5) and x = Float.abs (!x -. sqrt3_2) in
      let dist1 = 2. *. z *. sqrt3 and dist2 = (((sqrt3 *. x) +. z) *. sqrt3) -. 1.5 in
      if six then fmax (6.0 -. fmin dist1 dist2) 5.000001 /. 6.0 else fmax (3.0 -. fmin dist1 dist2) 2.0000001 /. 3.0
    end
    else if !z < 0.5 then
      if !x > sqrt3_2 +. 0.5 then begin
        (* a square *)
        let x = !x -. (sqrt3_2 +. 0.5) and z = !z -. 0.5 in
        let dist1 = fmax (1.0 +. (z *. 2. *. sqrt3)) 0.0 and dist2 = fmax (1.0 -. (x *. 2. *. sqrt3)) 0.0 in
        if six then
          (fmax dist1 dist2 +. (float_of_int !rota *. (1.000001 +. float_of_int ((!mir_x + !mir_z) mod 2)))) /. 6.0
        else fmax dist1 dist2 /. 3.0
      end
      else begin
        (* a triangle *)
        let x = Float.abs (!x -. (sqrt3_2 +. 0.5)) in
        let dist2 = (((sqrt3 *. !z) +. x) *. sqrt3) +. 0.5 and dist1 = 2.0 -. (x *. 2.0 *. sqrt3) in
        if six then
          let answer = fmax dist1 dist2 in
          (if (!rota + !mir_x) mod 2 <> 0 then 2.0 +. answer else 3.0 +. answer) /. 6.0
        else fmax dist1 dist2 /. 3.0
      end
    else 0.

  let rectangle_pair (p : Vec.t) =
    let x = ref (p.x -. (4.0 *. floor (p.x /. 4.0))) and z = ref (p.z -. (4.0 *. floor (p.z /. 4.0))) in
    let delta = ref 1.0 in
    (* the corner of the cell's rectangle, and whether it lies along x (delta 0) *)
    let dx, dz, along_x =
      match c_int !x + (c_int !z * 4) with
      | 0 | 4 -> (0.0, 1.0, false)
      | 1 | 5 -> (1.0, 1.0, false)
      | 2 | 3 -> (3.0, 0.0, true)
      | 6 | 7 -> (3.0, 1.0, true)
      | 8 | 9 -> (1.0, 2.0, true)
      | 12 | 13 -> (1.0, 3.0, true)
      | 10 | 14 -> (2.0, 3.0, false)
      | 11 | 15 -> (3.0, 3.0, false)
      | _ -> (0.0, 0.0, false)
    in
    x := !x -. dx;
    z := !z -. dz;
    if along_x then delta := 0.0;
    let x, z =
      if !delta = 1.0 then (2. *. Float.abs (!x -. 0.5), 2. *. (fmax (Float.abs !z) 0.5 -. 0.5))
      else (2. *. (fmax (Float.abs !x) 0.5 -. 0.5), 2. *. Float.abs (!z -. 0.5))
    in
    Float.abs ((fmax x z +. !delta) /. 2.0)

  (* tilings 19 and 20: hexagons ringed by triangles, the rows shifted right or left; once the
     point is in the cell [0,7) × [0,3√3/2), the triangles and hexagons are found alike *)
  let[@inline] hexa_tri_cell x z =
    let x = ref x and z = ref z and delta = ref 0 in
    let zzof = c_int (!z /. sqrt3_2) in
    let zzof =
      if zzof = 2 then begin
        z := (2. *. sqrt3) -. !z;
        delta := 1 - !delta;
        1
      end
      else zzof
    in
    if zzof = 0 || !x > 2.0 || !z +. (sqrt3 *. !x) < sqrt3 || (sqrt3 *. !x) -. !z > sqrt3 then begin
      (* a triangle *)
      x := !x -. (1.0 *. floor (!x /. 1.0));
      z := !z -. (sqrt3 *. floor (!z /. sqrt3));
      if !z > sqrt3_2 then begin
        z := sqrt3 -. !z;
        delta := 1 - !delta
      end;
      if !x > 0.5 then x := 1.0 -. !x;
      if !x <> 0.0 then begin
        if !z /. !x > sqrt3 then begin
          z := sqrt3_2 -. !z;
          x := 0.5 -. !x;
          delta := 1 - !delta
        end
      end
      else begin
        z := sqrt3_2 -. !z;
        x := 0.5;
        delta := 1 - !delta
      end;
      let dist1 = 1.0 -. (!z *. 2. *. sqrt3) and dist2 = 1.0 -. (((sqrt3 *. !x) -. !z) *. sqrt3) in
      (float_of_int !delta +. fmax dist1 dist2) /. 3.0
    end
    else begin
      (* a hexagon *)
      z := !z -. sqrt3_2;
      if !x > 1.0 then x := 2.0 -. !x;
      let dist1 = 2. +. (2. *. (!z *. sqrt3)) and dist2 = 2. +. (2. *. ((sqrt3 *. !x) +. !z -. sqrt3_2) *. sqrt3_2) in
      fmax (5.0 -. fmin dist1 dist2) 2.000001 /. 3.0
    end

  (* the row of three half-heights the point is in, −1 below the axis; each shifts the rows by
     half a unit *)
  let[@inline] hexa_tri_rows z =
    let zzof = c_int (z /. sqrt3_2) / 3 in
    if z < 0. then zzof - 1 else zzof

  let hexa_tri_right (p : Vec.t) =
    let x = ref (p.x +. (float_of_int (hexa_tri_rows p.z) /. 2.0)) in
    let z = ref (p.z -. (3. *. sqrt3_2 *. floor (p.z /. (3. *. sqrt3_2)))) in
    x := !x +. 7.0;
    x := !x -. (7.0 *. floor (!x /. 7.0));
    if !x > 4.5 && !z > sqrt3 then begin
      x := !x -. 4.5;
      z := !z -. sqrt3_2
    end;
    if !x > 5.0 && !z < sqrt3_2 then begin
      x := !x -. 5.;
      z := !z +. sqrt3
    end;
    if !x > 2.5 && !z < sqrt3 then begin
      x := !x -. 2.5;
      z := !z +. sqrt3_2
    end;
    hexa_tri_cell !x !z

  let hexa_tri_left (p : Vec.t) =
    let x = ref (p.x -. (float_of_int (hexa_tri_rows p.z) /. 2.0)) in
    let z = ref (p.z -. (3. *. sqrt3_2 *. floor (p.z /. (3. *. sqrt3_2)))) in
    x := !x +. 7.0;
    x := !x -. (7.0 *. floor (!x /. 7.0));
    if !x > 2.0 && !z < sqrt3_2 then begin
      x := !x -. 2.0;
      z := !z +. sqrt3
    end;
    if !x > 4.5 && !z < sqrt3 then begin
      x := !x -. 4.5;
      z := !z +. sqrt3_2
    end;
    if !x > 2.5 && !z > sqrt3 then begin
      x := !x -. 2.5;
      z := !z -. sqrt3_2
    end;
    hexa_tri_cell !x !z

  let square_tri (p : Vec.t) =
    let period = 1.0 +. sqrt3 in
    let x = ref (p.x -. (period *. floor (p.x /. period))) and z = ref (p.z -. (period *. floor (p.z /. period))) in
    let delta = ref 0 and beta = ref 0 in
    if !z > 0.5 +. sqrt3_2 then begin
      z := 1.0 +. sqrt3 -. !z;
      delta := 1 - !delta
    end;
    if !x > 0.5 +. sqrt3_2 then begin
      x := 1.0 +. sqrt3 -. !x;
      delta := 1 - !delta;
      beta := 1
    end;
    (* [0, (1+√3)/2]²: still a mirror and a rotation *)
    let xflop = (2.0 *. !x) +. ((sqrt3 -. 1.0) *. 2.0 *. !z /. (sqrt3 +. 1.0)) > sqrt3 in
    let zflop = (2.0 *. !z *. sqrt3) +. ((sqrt3 -. 3.0) *. 2.0 *. !x /. (sqrt3 +. 1.0)) > sqrt3 in
    let delta = !delta and beta = !beta in
    let gamma =
      match (xflop, zflop) with
      | false, false -> 2 * beta
      | true, false ->
          let s = !x in
          x := !z;
          z := sqrt3_2 +. 0.5 -. s;
          if beta <> 0 then 1 + (2 * delta) else 3 - (2 * delta)
      | false, true ->
          let s = !z in
          z := !x;
          x := sqrt3_2 +. 0.5 -. s;
          if beta <> 0 then 3 - (2 * delta) else 1 + (2 * delta)
      | true, true ->
          x := sqrt3_2 +. 0.5 -. !x;
          z := sqrt3_2 +. 0.5 -. !z;
          if beta <> 0 then 0 else 2
    in
    if !x = 0.0 then begin
      z := 0.0;
      x := 0.0
    end;
    let slop1 = (!z *. 2. *. sqrt3) -. sqrt3 +. (!x *. 2.) in
    if slop1 < 0. then
      (* a triangle *)
      let dist1 = -1.5 /. sqrt3 *. slop1 and dist2 = 2.0 *. !x *. sqrt3 in
      (float_of_int gamma +. 1.0 -. fmin dist1 dist2) /. 6.0
    else
      (* a square *)
      let s = fmin (slop1 *. (1.5 /. sqrt3)) 1.0 in
      if delta <> 0 then fmin (fmax (((s *. -1.) +. 6.0) /. 6.0) (5.000001 /. 6.0)) 1.0
      else fmax (fmin (((s *. -1.) +. 5.0) /. 6.0) (5.0 /. 6.0)) (4.000001 /. 6.0)

  let dodeca_tri (p : Vec.t) =
    let x = ref (p.x -. ((2.0 +. sqrt3) *. floor (p.x /. (2.0 +. sqrt3)))) in
    let z = ref (p.z -. ((3.0 +. (2.0 *. sqrt3)) *. floor (p.z /. (3.0 +. (2.0 *. sqrt3))))) in
    let toggle = ref 0 in
    if !z > sqrt3 +. 1.5 then begin
      z := !z -. (sqrt3 +. 1.5);
      x := !x +. ((if !x < 1.0 +. sqrt3_2 then 1.0 else -1.0) *. (1.0 +. sqrt3_2))
    end;
    if !x > 1.0 +. sqrt3_2 then x := 2.0 +. sqrt3 -. !x;
    if !z > 1.0 +. sqrt3_2 then begin
      z := 2.0 +. sqrt3 -. !z;
      toggle := 1 - !toggle
    end;
    let dist2 = ref (!x -. sqrt3_2 -. 0.5 +. (!z *. sqrt3)) in
    if !dist2 < 0.0 then begin
      let tmpx = !x and tmpz = !z in
      x := ((1.0 +. sqrt3) /. 4.0) +. (0.5 *. tmpx) -. (sqrt3_2 *. tmpz);
      z := ((3.0 +. sqrt3) /. 4.0) -. (sqrt3_2 *. tmpx) -. (0.5 *. tmpz);
      dist2 := !dist2 *. -1.0
    end;
    let dist1 = !z *. 3.0 in
    let dist3 = (!z -. sqrt3_2 -. 0.5 +. (!x *. sqrt3)) *. sqrt3 in
    let dist2 = !dist2 *. sqrt3 in
    let dist4 = !x *. 3.0 in
    if dist3 < 0.0 then (fmax dist3 (-1.0) +. float_of_int (1 + !toggle)) /. 3.0
    else
      (* the dodecagon *)
      let r = fmin (fmin (fmin (fmin dist1 dist2) dist3) dist4) 1.0 in
      (3.0000001 -. r) /. 3.0

  (* dodecagons, hexagons and squares in [0, 3+√3) × [0, 3+3√3): tilings 23 and 24 *)
  let dodeca_hex_n five (p : Vec.t) =
    let x = ref (p.x -. ((3.0 +. sqrt3) *. floor (p.x /. (3.0 +. sqrt3)))) in
    let z = ref (p.z -. ((3.0 +. (3.0 *. sqrt3)) *. floor (p.z /. (3.0 +. (3.0 *. sqrt3))))) in
    let mir_x = ref 0 and mir_z = ref 0 in
    if !z > (1.5 *. sqrt3) +. 1.5 then begin
      z := !z -. ((1.5 *. sqrt3) +. 1.5);
      x := !x +. ((if !x < 1.5 +. sqrt3_2 then 1.0 else -1.0) *. (1.5 +. sqrt3_2))
    end;
    if !x > 1.5 +. sqrt3_2 then begin
      x := 3.0 +. sqrt3 -. !x;
      mir_x := 1 - !mir_x
    end;
    if !z > 1.0 +. sqrt3 then begin
      z := 2.0 +. (2.0 *. sqrt3) -. !z;
      mir_z := 1 - !mir_z
    end;
    if !x -. sqrt3_2 -. 1.5 +. (!z *. sqrt3) < 0.0 then begin
      let tmpx = !x and tmpz = !z in
      x := ((3.0 +. sqrt3) /. 4.0) +. (0.5 *. tmpx) -. (sqrt3_2 *. tmpz);
      z := ((3.0 +. (3.0 *. sqrt3)) /. 4.0) -. (sqrt3_2 *. tmpx) -. (0.5 *. tmpz)
    end;
    let x = !x and z = !z in
    let dist2 = x -. sqrt3_2 -. 2.5 +. (z *. sqrt3) in
    let dist1 = (z *. 2.0) -. sqrt3 in
    let dist3 = z -. (1.5 *. sqrt3) -. 0.5 +. (x *. sqrt3) in
    let dist4 = (x -. 0.5) *. 2.0 in
    let r =
      if dist2 >= 0.0 && dist1 >= 0.0 && dist3 >= 0.0 && dist4 >= 0.0 then
        (* the dodecagon *)
        let r = fmin (fmin (fmin (fmin dist1 dist2) dist3) dist4) 1.0 in
        (if five then 5.000001 else 3.000001) -. r
      else
        let dist5 = (2. *. z) -. (2. *. sqrt3) -. 1.0 in
        if dist5 >= 0. then 2.0 -. fmin dist5 (dist4 *. -1.0)
        else
          let dist6 = (sqrt3 *. x) -. z -. sqrt3_2 +. 0.5 in
          let dist7 = dist6 -. 2.0 in
          match (if dist6 >= 0. then 0 else 1) + if dist7 >= 0.0 then 2 else 0 with
          | 1 ->
              (* the hexagon on the left *)
              1.0 -. fmin (fmin (fmin (dist6 *. -1.0) (dist3 *. -1.0)) (dist5 *. -1.0)) 1.0
          | 2 ->
              (* the hexagon below *)
              1.0 -. fmin (fmin dist7 (dist1 *. -1.0)) 1.0
          | _ ->
              (* the slanted square *)
              let r = fmin (fmin dist6 (dist2 *. -1.0)) (dist7 *. -1.0) in
              if five then float_of_int ((!mir_z + !mir_x) mod 2) +. 3.0 -. r else 2.0 -. r
    in
    r /. if five then 5.0 else 3.0

  (* Penrose's P2 (kites and darts) and P3 (rhombs): the point, scaled up by φ each step, is
     taken down [depth] levels of the substitution of half-kites and half-darts; the tile it ends
     in gives the value *)
  let penrose_halves x z depth rhombs =
    let x = ref x and z = ref z and depth = ref depth and kite = ref true and result = ref 0. and fin = ref false in
    while not !fin do
      let px = !x and pz = Float.abs !z in
      if !kite then
        if !depth > 0 then begin
          if pz < (px -. invphi) *. tan144 then begin
            x := px *. phi;
            z := pz *. phi;
            kite := false
          end
          else begin
            let x1 = px -. cos36 and z1 = pz -. sin36 in
            let rot_x = (x1 *. cos108) -. (z1 *. sin108) and rot_z = (z1 *. cos108) +. (x1 *. sin108) in
            x := rot_x *. phi;
            z := rot_z *. phi
          end;
          decr depth
        end
        else begin
          fin := true;
          result :=
            if rhombs then
              if pz < (px -. invphi) *. tan72 then
                let dist1 = Float.abs ((sin72 *. (px -. invphi)) -. (cos72 *. pz)) *. 5.55
                and dist2 = Float.abs ((sin108 *. (px -. 1.)) -. (cos108 *. pz)) *. 5.55 in
                max3 (1.0 -. (dist1 /. 2.)) (1.0 -. (dist2 /. 2.)) (0.5 +. tiling_epsilon)
              else
                let dist1 = Float.abs pz *. 5.55
                and dist2 = Float.abs ((sin72 *. (px -. invphi)) -. (cos72 *. pz)) *. 5.55 in
                fmin (max3 (0.5 -. (dist1 /. 2.)) (0.5 -. (dist2 /. 2.)) 0.0) (0.5 -. tiling_epsilon)
            else
              let dist1 = Float.abs ((sin36 *. px) -. (cos36 *. pz)) *. 4.46
              and dist2 = Float.abs ((sin108 *. (px -. 1.)) -. (cos108 *. pz)) *. 4.46 in
              fmin (max3 (0.5 -. (dist1 /. 2.)) (0.5 -. (dist2 /. 2.)) 0.0) (0.5 -. tiling_epsilon)
        end
      else if !depth > 0 then begin
        if pz < (px -. invphi) *. -.tan72 then begin
          let rot_x = (px *. cos36) +. (pz *. sin36) and rot_z = (pz *. cos36) -. (px *. sin36) in
          x := rot_x *. phi;
          z := rot_z *. phi;
          kite := true
        end
        else begin
          let x1 = px -. 1. in
          let rot_x = (x1 *. cos144) +. (pz *. sin144) and rot_z = (pz *. cos144) -. (x1 *. sin144) in
          x := rot_x *. phi;
          z := rot_z *. phi
        end;
        decr depth
      end
      else begin
        fin := true;
        result :=
          if rhombs then
            let dist1 = Float.abs ((sin36 *. px) -. (cos36 *. pz)) *. 5.55
            and dist2 = Float.abs ((sin144 *. (px -. 1.)) -. (cos144 *. pz)) *. 5.55 in
            fmin (max3 (0.5 -. (dist1 /. 2.)) (0.5 -. (dist2 /. 2.)) 0.0) (0.5 -. tiling_epsilon)
          else
            let dist1 = Float.abs pz *. 4.46 and dist2 = Float.abs ((sin144 *. (px -. 1.)) -. (cos144 *. pz)) *. 4.46 in
            max3 (1.0 -. (dist1 /. 2.)) (1.0 -. (dist2 /. 2.)) (0.5 +. tiling_epsilon)
      end
    done;
    !result

  (* the five-fold symmetry: z made positive, and a point outside the wedge of ±36° about +x
     turned into it; [r] is the point's distance from the origin *)
  let into_wedge (s : point2) r =
    s.pz <- Float.abs s.pz;
    if s.px < r *. cos36 then begin
      let far = s.px < r *. cos108 in
      let rot_sin = if far then sin144 else sin72 and rot_cos = if far then cos144 else cos72 in
      let rot_x = (s.px *. rot_cos) +. (s.pz *. rot_sin) and rot_z = (s.pz *. rot_cos) -. (s.px *. rot_sin) in
      s.px <- rot_x;
      s.pz <- Float.abs rot_z
    end

  let[@inline] distance (s : point2) = sqrt ((s.px *. s.px) +. (s.pz *. s.pz))

  let penrose rhombs centre (p : Vec.t) =
    let s = { px = p.x; pz = p.z } in
    let r = distance s in
    if r <= Precision.epsilon then 1.0
    else begin
      into_wedge s r;
      if rhombs then begin
        s.px <- s.px *. invphi;
        s.pz <- s.pz *. invphi
      end;
      let dist = Float.abs ((sin108 *. s.px) -. (cos108 *. s.pz)) /. cos18 in
      let depth = max 0 (c_int (ceil (log dist /. log sqrphi))) in
      let k = Float.pow invsqrphi (float_of_int depth) in
      s.px <- s.px *. k;
      s.pz <- s.pz *. k;
      if depth mod 2 <> 0 then begin
        let rot_x = (s.px *. cos36) +. (s.pz *. sin36) and rot_z = (s.pz *. cos36) -. (s.px *. sin36) in
        s.px <- rot_x;
        s.pz <- Float.abs rot_z
      end;
      let depth = depth * 2 in
      if centre then begin
        s.px <- s.px *. invphi;
        s.pz <- s.pz *. invphi;
        penrose_halves s.px s.pz (depth + 1) rhombs
      end
      else penrose_halves s.px s.pz depth rhombs
    end

  (* Penrose's P1: pentagons (three kinds), stars, boats and diamonds, taken down the
     substitution as above; some tiles have a side (inside the quad, the wedge, side A) *)
  type p1_tile = Pentagon1 | Pentagon2 | Pentagon3 | Star | Boat | Diamond

  let pentagon_dist x = Float.abs (x -. (0.5 /. tan36)) *. 5.55 *. invphi

  let penrose1_tiles x z depth =
    let s = { px = x; pz = z } in
    let depth = ref depth and tile = ref Pentagon1 and side = ref false in
    let result = ref 0. and fin = ref false in
    (* one level down: the tile the point is in, and the point in that tile's frame *)
    let go t sd px pz =
      tile := t;
      side := sd;
      s.px <- px *. phi;
      s.pz <- pz *. phi;
      decr depth
    in
    while not !fin do
      s.pz <- Float.abs s.pz;
      let deep = !depth > 0 in
      match !tile with
      | Pentagon1 ->
          into_wedge s (distance s);
          let px = s.px and pz = s.pz in
          if deep then
            if pz < ((px -. (0.5 /. tan36)) *. tan54) +. 0.5 then
              go Pentagon2 false (px -. (0.5 /. tan36) -. (invphi *. 0.5 *. cos72 /. sin36)) pz
            else go Star false ((px *. cos36) +. (pz *. sin36)) ((pz *. cos36) -. (px *. sin36))
          else begin
            fin := true;
            result := fmin (fmax ((1.0 /. 6.) -. (pentagon_dist px /. 6.)) 0.0) ((1.0 /. 6.) -. tiling_epsilon)
          end
      | Pentagon2 ->
          let px = s.px and pz = s.pz in
          if deep then
            if !side then
              if pz < (px -. (invsqrphi *. 0.5 /. sin36)) *. tan54 then go Pentagon1 false (px -. (0.5 /. sin36)) pz
              else if pz < (px -. (invsqrphi *. 0.5 /. sin36)) *. tan162 then go Diamond true (-.px) pz
              else
                go Pentagon2 true
                  ((px *. cos108) -. (pz *. sin108) +. (invphi *. 0.5 /. sin36))
                  ((pz *. cos108) +. (px *. sin108))
            else if pz < (px +. (0.5 /. sin36)) *. tan18 then
              go Diamond false (px +. (0.5 /. sin36) -. (invsqrphi *. 0.5 /. sin36)) pz
            else
              go Pentagon3 false
                (-.((px *. cos36) +. (pz *. sin36)) -. (cos72 *. 0.5 /. sin36))
                ((pz *. cos36) -. (px *. sin36) -. (sin72 *. 0.5 /. sin36))
          else begin
            into_wedge s (distance s);
            fin := true;
            result :=
              fmin
                (fmax ((2.0 /. 6.) -. (pentagon_dist s.px /. 6.)) ((1.0 /. 6.) +. tiling_epsilon))
                ((2.0 /. 6.) -. tiling_epsilon)
          end
      | Pentagon3 ->
          let px = s.px and pz = s.pz and wedge = !side in
          if deep then
            if wedge && px > invsqrphi *. 0.5 *. cos72 /. sin36 then
              go Pentagon2 true (-.(px -. (invsqrphi *. 0.5 *. cos72 /. sin36) -. (invphi *. 0.5 /. tan36))) pz
            else if (not wedge) && px < 0.5 *. cos108 /. sin36 then
              go Pentagon2 false ((px *. cos144) +. (pz *. sin144) -. (0.5 /. sin36)) ((pz *. cos144) -. (px *. sin144))
            else if (not wedge) && pz > (px -. (invsqrphi *. 0.5 /. sin36)) *. tan126 then
              go Pentagon3 false
                (-.((px *. cos36) -. (pz *. sin36)) -. (cos72 *. 0.5 /. sin36))
                ((pz *. cos36) +. (px *. sin36) -. (sin72 *. 0.5 /. sin36))
            else go Boat wedge px pz
          else begin
            into_wedge s (distance s);
            fin := true;
            result :=
              fmin
                (fmax ((3.0 /. 6.) -. (pentagon_dist s.px /. 6.)) ((2.0 /. 6.) +. tiling_epsilon))
                ((3.0 /. 6.) -. tiling_epsilon)
          end
      | Star ->
          let px = s.px and pz = s.pz in
          if deep then
            if px < invphi *. 0.5 /. tan36 then go Pentagon1 false px pz
            else go Pentagon3 true (-.(px -. (invphi /. tan36))) pz
          else begin
            fin := true;
            let dist = Float.abs ((sin162 *. (px -. (phi *. 0.5 /. sin36))) -. (cos162 *. pz)) *. 5.55 *. invphi in
            result :=
              fmin (fmax ((4.0 /. 6.) -. (dist /. 6.)) ((3.0 /. 6.) +. tiling_epsilon)) ((4.0 /. 6.) -. tiling_epsilon)
          end
      | Boat ->
          let px = s.px and pz = s.pz and wedge = !side in
          if deep then
            if wedge && px > phi *. 0.5 *. cos108 /. sin36 then go Pentagon1 false (-.px) pz
            else
              let rot_x = if wedge then px else (px *. cos72) -. (pz *. sin72)
              and rot_z = if wedge then pz else (pz *. cos72) +. (px *. sin72) in
              go Pentagon3 true (rot_x +. (0.5 /. sin36)) rot_z
          else begin
            fin := true;
            let dist1 = Float.abs (px -. (invphi *. 0.5 *. cos72 /. sin36)) *. 5.55 *. invphi in
            s.px <- -.px;
            into_wedge s (distance s);
            let dist2 = Float.abs ((sin162 *. (s.px -. (phi *. 0.5 /. sin36))) -. (cos162 *. s.pz)) *. 5.55 *. invphi in
            result :=
              fmin
                (max3 ((5.0 /. 6.) -. (dist1 /. 6.)) ((5.0 /. 6.) -. (dist2 /. 6.)) ((4.0 /. 6.) +. tiling_epsilon))
                ((5.0 /. 6.) -. tiling_epsilon)
          end
      | Diamond ->
          let px = s.px and pz = s.pz in
          if deep then if !side then go Pentagon1 false px pz else go Pentagon3 true px pz
          else begin
            fin := true;
            let dist = Float.abs ((sin18 *. (px +. (invphi *. 0.5 /. sin36))) -. (cos18 *. pz)) *. 5.55 *. invphi in
            result :=
              fmin (fmax ((6.0 /. 6.) -. (dist /. 6.)) ((5.0 /. 6.) +. tiling_epsilon)) ((6.0 /. 6.) -. tiling_epsilon)
          end
    done;
    !result

  let penrose1 (p : Vec.t) =
    let s = { px = p.x; pz = p.z } in
    let r = distance s in
    if r <= Precision.epsilon then 1.0
    else begin
      into_wedge s r;
      let dist = s.px *. 2. *. tan36 in
      let depth = max 0 (c_int (ceil (log dist /. log (sqrphi *. sqrphi)))) in
      let k = Float.pow (invsqrphi *. invsqrphi) (float_of_int depth) in
      penrose1_tiles (s.px *. k) (s.pz *. k) (depth * 4)
    end

  (* the tilings by number: 1 squares, 2 hexagons, 3 triangles, 4 lozenges, 5 rhombs, 6 and 18
     rectangles, 7 octagons and squares, 8 and 21 squares and triangles, 9 hexagons and
     triangles, 10 offset squares, 11 and 12 squares and rectangles, 13 and 14 squares at 45° in
     squares, 15 squares of two sizes, 16 and 17 hexagons, squares and triangles, 19 and 20
     hexagons and triangles in shifted rows, 22 dodecagons and triangles, 23 and 24 dodecagons,
     hexagons and squares, 25 Penrose's P1, 26 his kites and darts, 27 his rhombs; any other
     number is 1, as in POV-Ray's switch *)
  let value n (p : Vec.t) =
    match n with
    | 27 -> penrose true false p
    | 26 -> penrose false false p
    | 25 -> penrose1 p
    | 24 -> dodeca_hex_n true p
    | 23 -> dodeca_hex_n false p
    | 22 -> dodeca_tri p
    | 21 -> square_tri p
    | 20 -> hexa_tri_left p
    | 19 -> hexa_tri_right p
    | 18 -> rectangle_pair p
    | 17 -> hexa_square_triangle_n true p
    | 16 -> hexa_square_triangle_n false p
    | 15 -> square_double p
    | 14 -> square_internal_5 p
    | 13 -> square_internal p
    | 12 -> rectangle_square p
    | 11 -> square_rectangle p
    | 10 -> square_offset p
    | 9 -> hexa_triangle p
    | 8 -> square_triangle p
    | 7 -> octa_square p
    | 6 -> rectangle p
    | 5 -> rhombus p
    | 4 -> lozenge p
    | 3 -> triangle p
    | 2 -> hexagon p
    | _ -> square p
end

(* ---------------------------------------------------------------------------------------------- *)
(* pavement: tilings of the XZ plane by polyominoes (4 sides), polyiamonds (3) and polyhexes (6),
   after J. Grimbert (pattern.cpp). A table gives, for each cell of the pattern's period, which
   edges of the cell are a tile's border and which corners are special (bits, below); the value
   is 0 inside a tile and rises to 1 at its border, shaped by [form], [interior] and [exterior]. *)

module Pavement = struct
  (* four sides, two tiles: by the row's parity *)
  let digon = [| 0x0E; 0x0B |]

  (* four sides, three tiles: 2 patterns, 3 columns by 2 rows *)
  let trigon =
    [|
      [| 0xD; 0x5; 0x7; 0xD; 0x5; 0x7 |];
      [| 0xE; 0xD; 0x16; 0x49; 0x7; 0xB |];
    |]

  (* four sides, four tiles: 5 patterns, 4 by 4 cells *)
  let tetragon =
    [|
      [| 0xD; 0x5; 0x5; 0x7; 0xD; 0x5; 0x5; 0x7; 0xD; 0x5; 0x5; 0x7; 0xD; 0x5; 0x5; 0x7 |];
      [| 0xE; 0xD; 0x5; 0x16; 0x49; 0x5; 0x7; 0xB; 0xE; 0xD; 0x5; 0x16; 0x49; 0x5; 0x7; 0xB |];
      [| 0xD; 0x34; 0x7; 0xB; 0x7; 0xB; 0xD; 0x34; 0xD; 0x34; 0x7; 0xB; 0x7; 0xB; 0xD; 0x34 |];
      [| 0xC; 0x6; 0xC; 0x6; 0x9; 0x3; 0x9; 0x3; 0xC; 0x6; 0xC; 0x6; 0x9; 0x3; 0x9; 0x3 |];
      [| 0x7; 0x2C; 0x7; 0x2C; 0xD; 0x83; 0xD; 0x83; 0x2C; 0x7; 0x2C; 0x7; 0x83; 0xD; 0x83; 0xD |];
    |]

  (* four sides, five tiles: 12 patterns of 10 cells *)
  let pentagon =
    [|
      [| 0xD; 0x5; 0x5; 0x5; 0x7; 0xD; 0x5; 0x5; 0x5; 0x7 |];
      [| 0xE; 0xD; 0x5; 0x5; 0x16; 0x49; 0x5; 0x5; 0x7; 0xB |];
      [| 0x7; 0xC; 0x6; 0xC; 0x24; 0xD; 0x81; 0x3; 0x9; 0x3 |];
      [| 0xD; 0x5; 0x34; 0x7; 0xB; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xD; 0xF0; 0x7; 0xB; 0xE; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xE; 0xA; 0x49; 0x5; 0x7; 0xD; 0x5; 0x16; 0xA; 0xB |];
      [| 0xB; 0xE; 0x49; 0x16; 0x49; 0x7; 0xD; 0x16; 0x49; 0x16 |];
      [| 0x2C; 0x5; 0x16; 0xB; 0xE; 0xB; 0xE; 0x49; 0x5; 0x83 |];
      [| 0xE; 0x49; 0x5; 0x16; 0xB; 0xE; 0x49; 0x5; 0x16; 0xB |];
      [| 0xE; 0xD; 0xC1; 0x16; 0xB; 0x49; 0x34; 0x7; 0xB; 0xE |];
      [| 0x7; 0x2C; 0x5; 0x7; 0x2C; 0xD; 0x83; 0xD; 0x5; 0x83 |];
      [| 0xD; 0x34; 0x7; 0xD; 0xC1; 0x7; 0xA; 0xB; 0xE; 0xA |];
    |]

  (* four sides, six tiles: 35 patterns of 12 cells *)
  let hexagon =
    [|
      [| 0xD; 0x5; 0x5; 0x5; 0x5; 0x7; 0xD; 0x5; 0x5; 0x5; 0x5; 0x7 |];
      [| 0x2C; 0x5; 0x5; 0x5; 0x7; 0xE; 0xB; 0xD; 0x5; 0x5; 0x5; 0x83 |];
      [| 0xD; 0x34; 0x5; 0x5; 0x7; 0xE; 0x7; 0xB; 0xD; 0x5; 0x5; 0xC1 |];
      [| 0xD; 0x5; 0x34; 0x5; 0x7; 0xE; 0x5; 0x7; 0xB; 0xD; 0x5; 0xC1 |];
      [| 0xD; 0x83; 0x2C; 0x5; 0x5; 0x7; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xC; 0x24; 0x5; 0x7; 0xC; 0x6; 0x9; 0x3; 0xD; 0x5; 0x81; 0x3 |];
      [| 0x7; 0xC; 0x6; 0xD; 0x14; 0x24; 0xD; 0x81; 0x41; 0x7; 0x9; 0x3 |];
      [| 0xD; 0x5; 0x83; 0x2C; 0x5; 0x7; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0x7; 0xC; 0x24; 0x7; 0xC; 0x24; 0xD; 0x81; 0x3; 0xD; 0x81; 0x3 |];
      [| 0xC; 0x4; 0x6; 0xC; 0x4; 0x6; 0x9; 0x1; 0x3; 0x9; 0x1; 0x3 |];
      [| 0xE; 0xD; 0x14; 0x6; 0x48; 0x6; 0x9; 0x12; 0x9; 0x41; 0x7; 0xB |];
      [| 0xD; 0x5; 0x16; 0x49; 0x16; 0xB; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xD; 0x34; 0x5; 0x16; 0xE; 0xB; 0xE; 0xB; 0x49; 0x5; 0xC1; 0x7 |];
      [| 0xD; 0x34; 0x7; 0x16; 0xA; 0xD; 0xA; 0x49; 0x7; 0xC1; 0x7; 0xD |];
      [| 0xD; 0x14; 0x82; 0xE; 0x9; 0x3; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xE; 0xD; 0xD0; 0x6; 0x9; 0x3; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xD; 0xF0; 0x5; 0x7; 0xE; 0xB; 0xE; 0xB; 0xD; 0x5; 0xF0; 0x7 |];
      [| 0xE; 0xB; 0xD; 0x5; 0x5; 0x92; 0x68; 0x5; 0x5; 0x7; 0xE; 0xB |];
      [| 0xE; 0x49; 0x5; 0x16; 0xA; 0xB; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xB; 0x2C; 0x5; 0x5; 0x83; 0xE; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xB; 0xA; 0x2C; 0x5; 0x5; 0x7; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0x2C; 0x5; 0x5; 0x16; 0xB; 0xE; 0xE; 0xB; 0x5; 0x83; 0x49; 0x5 |];
      [| 0xA; 0xD; 0xC1; 0x16; 0x49; 0x34; 0x7; 0xA; 0xE; 0xB; 0xE; 0xB |];
      [| 0xD; 0x16; 0xD; 0x5; 0x92; 0xB; 0xE; 0x68; 0x5; 0x7; 0x49; 0x7 |];
      [| 0xD; 0x16; 0xD; 0x16; 0x16; 0x49; 0x16; 0x49; 0x49; 0x7; 0x49; 0x7 |];
      [| 0xC; 0x6; 0xC; 0x6; 0x9; 0x12; 0x9; 0x12; 0x7; 0x49; 0x7; 0x49 |];
      [| 0x2C; 0x7; 0x2C; 0x7; 0x92; 0xD; 0x92; 0xD; 0x49; 0x7; 0x49; 0x7 |];
      [| 0xE; 0x49; 0x5; 0x16; 0x49; 0x7; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xD; 0x16; 0xB; 0xE; 0x49; 0x7; 0x16; 0x49; 0x5; 0x83; 0x2C; 0x5 |];
      [| 0x7; 0xE; 0x49; 0x34; 0x7; 0x49; 0xD; 0xC1; 0x16; 0xB; 0xD; 0x16 |];
      [| 0x2C; 0x5; 0xC1; 0x7; 0xE; 0xB; 0xB; 0xD; 0x34; 0x5; 0x83; 0xE |];
      [| 0xE; 0xB; 0xD; 0x34; 0xC1; 0x7; 0xF; 0xF; 0xF; 0xF; 0xF; 0xF |];
      [| 0xD; 0x5; 0x16; 0x2C; 0x7; 0xA; 0xA; 0xD; 0x83; 0x49; 0x5; 0x7 |];
      [| 0x2C; 0xC1; 0x5; 0x7; 0xE; 0xB; 0xE; 0xB; 0xD; 0x5; 0x34; 0x83 |];
      [| 0xA; 0xD; 0x5; 0x92; 0x68; 0x5; 0x7; 0xA; 0xB; 0xE; 0xE; 0xB |];
    |]

  (* three sides, three tiles: 1 pattern of 6 triangles *)
  let tritrigon =
    [|
      [| 0x215; 0x344; 0x126; 0x126; 0x344; 0x215 |];
    |]

  (* three sides, four tiles: 3 patterns of 8 triangles *)
  let tritetragon =
    [|
      [| 0x126; 0x126; 0x144; 0x144; 0x126; 0x126; 0x144; 0x144 |];
      [| 0x611; 0x344; 0x126; 0x423; 0x611; 0x344; 0x126; 0x423 |];
      [| 0x5; 0x0; 0x6; 0x3; 0x0; 0x5; 0x3; 0x6 |];
    |]

  (* three sides, five tiles: 4 patterns of 10 triangles *)
  let tripentagon =
    [|
      [| 0x215; 0x244; 0x4; 0x144; 0x126; 0x126; 0x144; 0x4; 0x244; 0x215 |];
      [| 0x215; 0x244; 0x244; 0x611; 0x611; 0x244; 0x244; 0x215; 0x423; 0x423 |];
      [| 0x146; 0x126; 0x344; 0x611; 0x611; 0x344; 0x126; 0x146; 0x522; 0x522 |];
      [| 0x5; 0x0; 0x244; 0x215; 0x3; 0x3; 0x215; 0x244; 0x0; 0x5 |];
    |]

  (* three sides, six tiles: 12 patterns of 12 triangles *)
  let trihexagon =
    [|
      [| 0x215; 0x244; 0x4; 0x4; 0x244; 0x215; 0x215; 0x244; 0x4; 0x4; 0x244; 0x215 |];
      [| 0x413; 0x522; 0x144; 0x4; 0x244; 0x215; 0x413; 0x522; 0x144; 0x4; 0x244; 0x215 |];
      [| 0x3; 0x126; 0x144; 0x0; 0x244; 0x215; 0x3; 0x126; 0x144; 0x0; 0x244; 0x215 |];
      [| 0x215; 0x244; 0x4; 0x0; 0x6; 0x3; 0x4; 0x244; 0x215; 0x3; 0x6; 0x0 |];
      [| 0x5; 0x0; 0x244; 0x215; 0x245; 0x211; 0x5; 0x211; 0x245; 0x215; 0x244; 0x0 |];
      [| 0x245; 0x211; 0x215; 0x244; 0x244; 0x211; 0x245; 0x211; 0x244; 0x244; 0x215; 0x211 |];
      [| 0x215; 0x244; 0x244; 0x611; 0x522; 0x146; 0x146; 0x522; 0x611; 0x244; 0x244; 0x215 |];
      [| 0x5; 0x0; 0x244; 0x215; 0x146; 0x122; 0x122; 0x146; 0x215; 0x244; 0x0; 0x5 |];
      [| 0x5; 0x0; 0x6; 0x126; 0x344; 0x211; 0x5; 0x211; 0x344; 0x126; 0x6; 0x0 |];
      [| 0x215; 0x344; 0x122; 0x122; 0x344; 0x215; 0x215; 0x344; 0x122; 0x122; 0x344; 0x215 |];
      [| 0x5; 0x0; 0x6; 0x6; 0x0; 0x5; 0x6; 0x0; 0x5; 0x5; 0x0; 0x6 |];
      [| 0x691; 0x3C4; 0x5A2; 0x5A2; 0x3C4; 0x691; 0x5A2; 0x3C4; 0x691; 0x691; 0x3C4; 0x5A2 |];
    |]

  (* six sides, one tile *)
  let hexmonogon =
    [|
      [| 0x691; 0x3C4; 0x5A2; 0x5A2; 0x3C4; 0x691 |];
    |]

  (* six sides, two tiles *)
  let hexdigon =
    [|
      [| 0x691; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x691; 0x5A2; 0x1C4; 0x6080; 0x6080; 0x1C4; 0x5A2 |];
    |]

  (* six sides, three tiles: 3 patterns of 36 triangles *)
  let hextrigon =
    [|
      [| 0x691; 0x3C4; 0x5A2; 0x5A2; 0x3C4; 0x691; 0x5A2; 0x3C4; 0x691; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x691; 0x3C4; 0x5A2 |];
      [| 0x691; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x691; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x691;
         0x2C4; 0x4080; 0x1080; 0x1080; 0x491; 0x5A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2; 0x491; 0x1080;
         0x1080; 0x4080; 0x2C4; 0x691; 0x4A2; 0x2080; 0x2080; 0x4080; 0x1C4; 0x5A2 |];
      [| 0x691; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2; 0x5A2; 0x1C4; 0x6080; 0x6080;
         0xC4; 0x5080; 0x5080; 0x2C4; 0x691; 0x5A2; 0x1C4; 0x6080; 0x6080; 0xC4; 0x5080; 0x5080; 0x2C4;
         0x691; 0x691; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2 |];
    |]

  (* six sides, four tiles: 7 patterns of 48 triangles *)
  let hextetragon =
    [|
      [| 0x691; 0x3C4; 0x5A2; 0x5A2; 0x3C4; 0x691; 0x5A2; 0x3C4; 0x691; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x691; 0x3C4; 0x5A2 |];
      [| 0x691; 0x2C4; 0x4080; 0x1080; 0x80; 0x2080; 0x4080; 0x2C4; 0x691; 0x291; 0x3C4; 0x1A2; 0x4080;
         0x1C4; 0x5A2; 0x1A2; 0x3C4; 0x291; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x80; 0x1080; 0x691; 0x2C4;
         0x4080; 0x1080; 0x80; 0x2080; 0x4080; 0x2C4; 0x691; 0x291; 0x3C4; 0x1A2; 0x4080; 0x1C4; 0x5A2;
         0x1A2; 0x3C4; 0x291; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x80; 0x1080 |];
      [| 0x691; 0x2C4; 0x5080; 0x5080; 0xC4; 0x6080; 0x6080; 0xC4; 0x5080; 0x5080; 0x2C4; 0x691; 0x5A2;
         0x3C4; 0x291; 0x291; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2; 0x691; 0x2C4;
         0x5080; 0x5080; 0xC4; 0x6080; 0x6080; 0xC4; 0x5080; 0x5080; 0x2C4; 0x691; 0x5A2; 0x3C4; 0x291;
         0x291; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2 |];
      [| 0x691; 0x3C4; 0x5A2; 0x4A2; 0x3080; 0x491; 0x1A2; 0x3C4; 0x691; 0x691; 0x3C4; 0x5A2; 0x6080;
         0x1C4; 0x5A2; 0x1A2; 0x3C4; 0x691; 0x5A2; 0x1C4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x491; 0x3080;
         0xA2; 0x5A2; 0x1C4; 0x6080; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0xA2; 0x491; 0x3080; 0x4A2;
         0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2 |];
      [| 0x691; 0x3C4; 0x1A2; 0x5A2; 0x1C4; 0x6080; 0x5080; 0x2C4; 0x691; 0x491; 0x3080; 0xA2; 0x291;
         0x3C4; 0x5A2; 0x4A2; 0x3080; 0x91; 0x5A2; 0x3C4; 0x291; 0x691; 0x2C4; 0x5080; 0x691; 0x2C4;
         0x5080; 0x5080; 0x2C4; 0x691; 0x1A2; 0x3C4; 0x691; 0x91; 0x3080; 0x4A2; 0x6080; 0x1C4; 0x5A2;
         0xA2; 0x3080; 0x491; 0x5A2; 0x1C4; 0x6080; 0x6080; 0x1C4; 0x5A2 |];
      [| 0x691; 0x3C4; 0x5A2; 0xA2; 0x3080; 0x491; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x691;
         0x2C4; 0x4080; 0x1080; 0x1080; 0x491; 0x5A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2; 0x491; 0x1080;
         0x1080; 0x4080; 0x2C4; 0x691; 0x4A2; 0x2080; 0x2080; 0x4080; 0x1C4; 0x5A2; 0x491; 0x3080;
         0xA2; 0x5A2; 0x3C4; 0x691; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2 |];
      [| 0x691; 0x3C4; 0x5A2; 0x1A2; 0x3C4; 0x691; 0x91; 0x3080; 0xA2; 0x5A2; 0x3C4; 0x291; 0x5080;
         0xC4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x4A2; 0x3080; 0x491; 0x691; 0x2C4; 0x5080; 0x91; 0x3080;
         0xA2; 0x5A2; 0x3C4; 0x291; 0x691; 0x3C4; 0x5A2; 0x1A2; 0x3C4; 0x691; 0x4A2; 0x3080; 0x491;
         0x691; 0x2C4; 0x5080; 0x5080; 0xC4; 0x6080; 0x6080; 0x1C4; 0x5A2 |];
    |]

  (* six sides, five tiles: 22 patterns of 60 triangles *)
  let hexpentagon =
    [|
      [| 0x691; 0x3C4; 0x5A2; 0x5A2; 0x3C4; 0x691; 0x5A2; 0x3C4; 0x691; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x691; 0x3C4; 0x5A2 |];
      [| 0x6080; 0x1C4; 0x5A2; 0x1A2; 0x3C4; 0x691; 0x5A2; 0x1C4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x491;
         0x3080; 0xA2; 0x5A2; 0x1C4; 0x6080; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0xA2; 0x491; 0x3080;
         0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491; 0x3080; 0x4A2;
         0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x691; 0x3C4; 0x5A2; 0x4A2;
         0x3080; 0x491; 0x1A2; 0x3C4; 0x691; 0x691; 0x3C4; 0x5A2 |];
      [| 0x691; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x691; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x691;
         0x2C4; 0x4080; 0x1080; 0x1080; 0x491; 0x5A2; 0x3C4; 0x691; 0x91; 0x3080; 0x4A2; 0x491; 0x3080;
         0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491; 0x3080; 0x4A2;
         0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x91; 0x691; 0x3C4; 0x5A2; 0x491; 0x1080; 0x1080; 0x4080;
         0x2C4; 0x691; 0x4A2; 0x2080; 0x2080; 0x4080; 0x1C4; 0x5A2 |];
      [| 0x691; 0x3C4; 0x5A2; 0xA2; 0x3080; 0x491; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x691;
         0x2C4; 0x4080; 0x1080; 0x1080; 0x491; 0x5A2; 0x3C4; 0x691; 0x91; 0x3080; 0x4A2; 0x491; 0x3080;
         0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x91; 0x691; 0x3C4; 0x5A2; 0x491; 0x1080; 0x1080;
         0x4080; 0x2C4; 0x691; 0x4A2; 0x2080; 0x2080; 0x4080; 0x1C4; 0x5A2; 0x491; 0x3080; 0xA2; 0x5A2;
         0x3C4; 0x691; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2 |];
      [| 0x6080; 0x1C4; 0x5A2; 0xA2; 0x3080; 0x491; 0x5A2; 0x1C4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x491;
         0x3080; 0xA2; 0x5A2; 0x1C4; 0x6080; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0xA2; 0x491; 0x3080;
         0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x691; 0x3C4; 0x5A2;
         0x4A2; 0x3080; 0x491; 0x5A2; 0x3C4; 0x691; 0x691; 0x3C4; 0x5A2; 0x491; 0x3080; 0x4A2; 0x5A2;
         0x3C4; 0x691; 0xA2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2 |];
      [| 0x691; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x691; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x491;
         0x1080; 0x80; 0x80; 0x1080; 0x491; 0x4A2; 0x2080; 0x2080; 0x4080; 0x1C4; 0x5A2; 0x491; 0x3080;
         0xA2; 0x5A2; 0x3C4; 0x691; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x691; 0x3C4; 0x5A2;
         0xA2; 0x3080; 0x491; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x491; 0x1080; 0x80; 0x80;
         0x1080; 0x491; 0x4A2; 0x2080; 0x2080; 0x4080; 0x1C4; 0x5A2 |];
      [| 0x691; 0x2C4; 0x4080; 0x1080; 0x1080; 0x491; 0x5A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2; 0x491;
         0x1080; 0x1080; 0x4080; 0x2C4; 0x691; 0x4A2; 0x2080; 0x80; 0x80; 0x2080; 0x4A2; 0x491; 0x1080;
         0x80; 0x80; 0x1080; 0x491; 0x4A2; 0x2080; 0x2080; 0x4080; 0x1C4; 0x5A2; 0x691; 0x3C4; 0x1A2;
         0x1A2; 0x3C4; 0x691; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x491; 0x1080; 0x80; 0x80;
         0x1080; 0x491; 0x4A2; 0x2080; 0x80; 0x80; 0x2080; 0x4A2 |];
      [| 0x6080; 0x1C4; 0x5A2; 0x5A2; 0x1C4; 0x4080; 0x691; 0x2C4; 0x4080; 0x4080; 0x2C4; 0x691;
         0x4080; 0x1C4; 0x5A2; 0x5A2; 0x1C4; 0x6080; 0x691; 0x3C4; 0x1A2; 0x5A2; 0x1C4; 0x6080; 0x491;
         0x3080; 0xA2; 0x4A2; 0x3080; 0x91; 0x491; 0x1080; 0x1080; 0x4A2; 0x2080; 0x2080; 0x691; 0x3C4;
         0x1A2; 0x1A2; 0x3C4; 0x691; 0x2080; 0x2080; 0x4A2; 0x1080; 0x1080; 0x491; 0x91; 0x3080; 0x4A2;
         0xA2; 0x3080; 0x491; 0x6080; 0x1C4; 0x5A2; 0x1A2; 0x3C4; 0x691 |];
      [| 0x6080; 0xC4; 0x5080; 0x5080; 0x2C4; 0x291; 0x5A2; 0x3C4; 0x291; 0x291; 0x2C4; 0x5080; 0x691;
         0x2C4; 0x5080; 0x5080; 0x2C4; 0x691; 0x5080; 0x2C4; 0x691; 0x91; 0x3080; 0x4A2; 0x91; 0x3080;
         0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x691; 0x3C4; 0x5A2;
         0xA2; 0x3080; 0x491; 0x5A2; 0x1C4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x691; 0x3C4; 0x1A2; 0x5A2;
         0x1C4; 0x6080; 0x1A2; 0x3C4; 0x291; 0x691; 0x3C4; 0x1A2 |];
      [| 0x691; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x691; 0x5080; 0xC4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x291;
         0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x291; 0x5A2; 0x1C4; 0x6080; 0x6080; 0xC4; 0x5080; 0x491; 0x3080;
         0xA2; 0x5A2; 0x3C4; 0x691; 0x6A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x691; 0x3C4; 0x5A2;
         0xA2; 0x3080; 0x491; 0x5080; 0xC4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x291; 0x3C4; 0x1A2; 0x1A2;
         0x3C4; 0x291; 0x5A2; 0x1C4; 0x6080; 0x6080; 0xC4; 0x5080 |];
      [| 0x691; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x691; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x491;
         0x1080; 0x80; 0x80; 0x1080; 0x91; 0x4A2; 0x2080; 0x2080; 0x4080; 0xC4; 0x5080; 0x691; 0x3C4;
         0x1A2; 0x5A2; 0x3C4; 0x291; 0x5080; 0x2C4; 0x691; 0x691; 0x2C4; 0x5080; 0x291; 0x3C4; 0x5A2;
         0x1A2; 0x3C4; 0x691; 0x5080; 0xC4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x91; 0x1080; 0x80; 0x80;
         0x1080; 0x491; 0x4A2; 0x2080; 0x2080; 0x4080; 0x1C4; 0x5A2 |];
      [| 0x291; 0x3C4; 0x5A2; 0x1A2; 0x3C4; 0x691; 0x4080; 0xC4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x4080;
         0xC4; 0x4080; 0x1080; 0x1080; 0x491; 0x5A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2; 0x491; 0x1080;
         0x1080; 0x4080; 0xC4; 0x4080; 0x4A2; 0x2080; 0x2080; 0x4080; 0xC4; 0x4080; 0x691; 0x3C4;
         0x1A2; 0x5A2; 0x3C4; 0x291; 0x1A2; 0x3C4; 0x691; 0x491; 0x1080; 0x1080; 0x2080; 0x2080; 0x4A2;
         0x4A2; 0x2080; 0x2080; 0x1080; 0x1080; 0x491; 0x691; 0x3C4; 0x1A2 |];
      [| 0x691; 0x2C4; 0x5080; 0x5080; 0x2C4; 0x691; 0x5080; 0x2C4; 0x691; 0x91; 0x3080; 0x4A2; 0x291;
         0x3C4; 0x5A2; 0xA2; 0x3080; 0x491; 0x5080; 0xC4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x291; 0x3C4;
         0x1A2; 0x1A2; 0x3C4; 0x291; 0x5A2; 0x1C4; 0x6080; 0x6080; 0xC4; 0x5080; 0x491; 0x3080; 0xA2;
         0x5A2; 0x3C4; 0x291; 0x4A2; 0x3080; 0x91; 0x691; 0x2C4; 0x5080; 0x691; 0x2C4; 0x5080; 0x5080;
         0x2C4; 0x691; 0x5A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2 |];
      [| 0x691; 0x3C4; 0x5A2; 0x5A2; 0x3C4; 0x691; 0x5A2; 0x3C4; 0x691; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x91; 0x4A2; 0x3080; 0x91; 0x691; 0x2C4; 0x5080; 0x691; 0x2C4;
         0x5080; 0x5080; 0x2C4; 0x291; 0x5080; 0x2C4; 0x291; 0x291; 0x2C4; 0x5080; 0x291; 0x2C4;
         0x5080; 0x5080; 0x2C4; 0x691; 0x5080; 0x2C4; 0x691; 0x91; 0x3080; 0x4A2; 0x91; 0x3080; 0x4A2;
         0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x691; 0x3C4; 0x5A2 |];
      [| 0x291; 0x3C4; 0x5A2; 0x5A2; 0x3C4; 0x691; 0x5A2; 0x3C4; 0x691; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x91; 0x4A2; 0x3080; 0x91; 0x691; 0x2C4; 0x5080; 0x691; 0x2C4;
         0x5080; 0x5080; 0x2C4; 0x291; 0x5080; 0x2C4; 0x291; 0x291; 0x2C4; 0x5080; 0x291; 0x2C4;
         0x5080; 0x5080; 0x2C4; 0x691; 0x5080; 0x2C4; 0x691; 0x291; 0x3C4; 0x5A2 |];
      [| 0x691; 0x2C4; 0x5080; 0x5080; 0xC4; 0x4080; 0x1A2; 0x3C4; 0x691; 0x291; 0x2C4; 0x4080; 0x2080;
         0x2080; 0x4A2; 0x5A2; 0x3C4; 0x691; 0x1080; 0x1080; 0x491; 0x491; 0x3080; 0x4A2; 0x91; 0x3080;
         0x4A2; 0x4A2; 0x3080; 0x91; 0x4A2; 0x3080; 0x491; 0x491; 0x1080; 0x1080; 0x691; 0x3C4; 0x5A2;
         0x4A2; 0x2080; 0x2080; 0x4080; 0x2C4; 0x291; 0x691; 0x3C4; 0x1A2; 0x4080; 0xC4; 0x5080;
         0x5080; 0x2C4; 0x691; 0x5A2; 0x3C4; 0x291; 0x291; 0x3C4; 0x5A2 |];
      [| 0x4080; 0x1C4; 0x1A2; 0x1A2; 0x1C4; 0x4080; 0x5A2; 0x1C4; 0x6080; 0x6080; 0xC4; 0x4080; 0x691;
         0x3C4; 0x1A2; 0x5A2; 0x3C4; 0x691; 0x1A2; 0x3C4; 0x691; 0x491; 0x3080; 0x4A2; 0x2080; 0x2080;
         0x4A2; 0x4A2; 0x3080; 0x91; 0x1080; 0x1080; 0x491; 0x491; 0x1080; 0x1080; 0x91; 0x3080; 0x4A2;
         0x4A2; 0x2080; 0x2080; 0x4A2; 0x3080; 0x491; 0x691; 0x3C4; 0x1A2; 0x691; 0x3C4; 0x5A2; 0x1A2;
         0x3C4; 0x691; 0x4080; 0xC4; 0x6080; 0x6080; 0x1C4; 0x5A2 |];
      [| 0x291; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x291; 0x5A2; 0x1C4; 0x6080; 0x6080; 0xC4; 0x5080; 0x691;
         0x3C4; 0x1A2; 0x5A2; 0x3C4; 0x691; 0x5080; 0x2C4; 0x691; 0x491; 0x3080; 0x4A2; 0x91; 0x3080;
         0x4A2; 0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491; 0x3080; 0x4A2;
         0x4A2; 0x3080; 0x91; 0x4A2; 0x3080; 0x491; 0x691; 0x2C4; 0x5080; 0x691; 0x3C4; 0x5A2; 0x1A2;
         0x3C4; 0x691; 0x5080; 0xC4; 0x6080; 0x6080; 0x1C4; 0x5A2 |];
      [| 0x91; 0x3080; 0x4A2; 0x5A2; 0x3C4; 0x691; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x691;
         0x3C4; 0x5A2; 0xA2; 0x3080; 0x91; 0x5A2; 0x1C4; 0x6080; 0x6080; 0xC4; 0x5080; 0x691; 0x3C4;
         0x1A2; 0x1A2; 0x3C4; 0x691; 0x5080; 0xC4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x91; 0x3080; 0xA2;
         0x5A2; 0x3C4; 0x691; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x691; 0x3C4; 0x5A2; 0x4A2;
         0x3080; 0x91; 0x5080; 0x2C4; 0x691; 0x691; 0x2C4; 0x5080 |];
      [| 0x691; 0x3C4; 0x1A2; 0x1A2; 0x3C4; 0x691; 0x5A2; 0x1C4; 0x4080; 0x2080; 0x2080; 0x4A2; 0x691;
         0x2C4; 0x4080; 0x1080; 0x1080; 0x91; 0x5080; 0x2C4; 0x691; 0x291; 0x2C4; 0x5080; 0x91; 0x3080;
         0x4A2; 0x5A2; 0x3C4; 0x691; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x691; 0x3C4; 0x5A2;
         0x4A2; 0x3080; 0x91; 0x5080; 0x2C4; 0x291; 0x691; 0x2C4; 0x5080; 0x91; 0x1080; 0x1080; 0x4080;
         0x2C4; 0x691; 0x4A2; 0x2080; 0x2080; 0x4080; 0x1C4; 0x5A2 |];
      [| 0x291; 0x3C4; 0x5A2; 0x5A2; 0x3C4; 0x691; 0x5A2; 0x3C4; 0x691; 0x491; 0x3080; 0x4A2; 0x491;
         0x3080; 0x4A2; 0x4A2; 0x3080; 0x91; 0x4A2; 0x3080; 0x91; 0x691; 0x2C4; 0x5080; 0x691; 0x2C4;
         0x5080; 0x5080; 0x2C4; 0x691; 0x5080; 0x2C4; 0x691; 0x91; 0x3080; 0x4A2; 0x91; 0x3080; 0x4A2;
         0x4A2; 0x3080; 0x91; 0x4A2; 0x3080; 0x91; 0x691; 0x2C4; 0x5080; 0x691; 0x2C4; 0x5080; 0x5080;
         0x2C4; 0x691; 0x5080; 0x2C4; 0x691; 0x291; 0x3C4; 0x5A2 |];
      [| 0x691; 0x3C4; 0x1A2; 0x5A2; 0x3C4; 0x291; 0x5080; 0x2C4; 0x691; 0x691; 0x2C4; 0x5080; 0x291;
         0x3C4; 0x5A2; 0x1A2; 0x3C4; 0x691; 0x5080; 0xC4; 0x6080; 0x6080; 0x1C4; 0x5A2; 0x91; 0x3080;
         0xA2; 0x5A2; 0x3C4; 0x691; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x491; 0x3080; 0x4A2;
         0x4A2; 0x3080; 0x491; 0x4A2; 0x3080; 0x491; 0x491; 0x3080; 0x4A2; 0x691; 0x3C4; 0x5A2; 0xA2;
         0x3080; 0x91; 0x5A2; 0x1C4; 0x6080; 0x6080; 0xC4; 0x5080 |];
    |]

  (* C's a % m taken into [0, m) *)
  let[@inline] pmod a m =
    let r = a mod m in
    if r < 0 then r + m else r

  (* the entry [i] of the [number]-th pattern (from 1) of a table *)
  let entry (table : int array array) number i =
    if number < 1 || number > Array.length table then invalid_arg "Patterns.value: pavement pattern number out of range"
    else table.(number - 1).(i)

  (* Squares. The cell [0,1)² of the unit grid, and its edges and corners:
       5---1---6
       |       |
       4       2        edges 1, 2, 3, 4 are the bits 0x01, 0x02, 0x04, 0x08 (z up),
       |       |        corners 5, 6, 7, 8 the bits 0x10, 0x20, 0x40, 0x80
       8---3---7 *)
  let tetragonal tile number form interior exterior (p : Vec.t) =
    let x = p.x and y = p.z in
    let zv = ref (int_of_float (floor y)) and xv = ref (int_of_float (floor x)) in
    let how =
      match tile with
      | 6 ->
          let lng =
            match number - 1 with
            | 0 | 1 | 2 | 3 | 5 | 6 | 8 | 9 ->
                xv := pmod !xv 6;
                zv := !zv land 1;
                6
            | 4 | 7 | 19 | 20 ->
                zv := pmod !zv 6;
                xv := pmod (!xv + (5 * !zv)) 6;
                0
            | 11 | 18 | 27 ->
                zv := pmod !zv 6;
                xv := pmod (!xv + !zv) 6;
                0
            | 10 | 12 | 21 | 22 | 24 | 25 | 26 ->
                xv := !xv land 3;
                zv := pmod !zv 3;
                4
            | 13 | 32 ->
                zv := !zv land 3;
                xv := pmod !xv 3;
                3
            | 14 ->
                zv := pmod !zv 6;
                xv := !xv + (2 * (!zv / 2));
                zv := !zv land 1;
                xv := pmod !xv 3;
                3
            | 15 ->
                xv := pmod !xv 6;
                zv := !zv + (!xv / 2);
                xv := !xv land 1;
                zv := pmod !zv 3;
                2
            | 16 | 17 ->
                zv := pmod !zv 12;
                xv := !xv + (!zv / 2);
                zv := !zv land 1;
                xv := pmod !xv 6;
                6
            | 23 | 28 ->
                zv := pmod !zv 12;
                xv := !xv + (4 * (!zv / 2));
                zv := !zv land 1;
                xv := pmod !xv 6;
                6
            | 29 | 30 ->
                zv := !zv land 3;
                xv := !xv + (3 * (!zv / 2));
                zv := !zv land 1;
                xv := pmod !xv 6;
                6
            | 31 ->
                zv := pmod !zv 3;
                xv := pmod (!xv + (4 * !zv)) 6;
                0
            | 33 ->
                zv := pmod !zv 12;
                xv := pmod (!xv + (7 * !zv)) 12;
                0
            | 34 ->
                zv := pmod !zv 6;
                xv := !xv + (2 * (!zv / 3));
                xv := !xv land 3;
                zv := pmod !zv 3;
                4
            | _ -> 0
          in
          entry hexagon number (!xv + (!zv * lng))
      | 5 ->
          (match number - 1 with
          | 0 | 1 ->
              xv := pmod !xv 5;
              zv := !zv land 1
          | 2 | 9 ->
              zv := pmod !zv 10;
              xv := pmod (!xv + (3 * (!zv / 2))) 5;
              zv := !zv land 1
          | 10 ->
              zv := pmod !zv 10;
              xv := pmod (!xv + (4 * (!zv / 2))) 5;
              zv := !zv land 1
          | 3 | 4 ->
              zv := pmod !zv 5;
              xv := pmod (!xv + (2 * !zv)) 5;
              zv := 0
          | 5 | 6 | 8 ->
              zv := pmod !zv 10;
              xv := pmod (!xv + !zv) 10;
              zv := 0
          | 11 ->
              zv := pmod !zv 10;
              xv := pmod (!xv + (8 * !zv)) 10;
              zv := 0
          | 7 ->
              zv := pmod !zv 10;
              xv := pmod (!xv + (3 * !zv)) 10;
              zv := 0
          | _ -> ());
          entry pentagon number (!xv + (!zv * 5))
      | 4 -> entry tetragon number ((!xv land 3) + ((!zv land 3) * 4))
      | 3 -> entry trigon number (pmod !xv 3 + ((!zv land 1) * 3))
      | 2 -> digon.(!zv land 1)
      | _ -> 0x0F
    in
    let x = x -. floor x and y = y -. floor y in
    (* a cell where the tile turns: two borders and the corner opposite them (0x16: edges 2 and 3
       with corner 5; 0x2C: 3, 4 and 6; 0x49: 1, 4 and 7; 0x83: 1, 2 and 8); forms 0, 1 and 2
       make the turn square, cut or round, and return at once *)
    let corner =
      if how land 0x16 = 0x16 then 1
      else if how land 0x2C = 0x2C then 2
      else if how land 0x49 = 0x49 then 3
      else if how land 0x83 = 0x83 then 4
      else 0
    in
    if corner <> 0 && form <= 2 then
      match form with
      | 2 ->
          (* a rounded corner *)
          let v1 = if corner = 1 || corner = 4 then 2. *. x else 2. -. (2. *. x)
          and v2 = if corner = 3 || corner = 4 then 2. *. y else 2. -. (2. *. y) in
          fmin (Float.abs (sqrt ((v1 *. v1) +. (v2 *. v2)) -. 1.0)) 1.0
      | 1 ->
          (* a cut corner *)
          let v1 = 2. *. x and v2 = if corner = 1 || corner = 3 then 2. *. y else 2. -. (2. *. y) in
          if corner = 1 || corner = 4 then fmin (Float.abs (v1 -. v2 +. 1.0)) 1.0
          else fmin (Float.abs (v2 -. v1 +. 1.0)) 1.0
      | _ ->
          (* a square corner *)
          let px = (2. *. x) -. 1. and nx = 1. -. (2. *. x) and py = (2. *. y) -. 1. and ny = 1. -. (2. *. y) in
          let right = corner = 1 || corner = 4 and top = corner = 1 || corner = 2 in
          fmax
            (fmax (if right then px else nx) (if top then ny else py))
            (fmin (if right then nx else px) (if top then py else ny))
    else begin
      let rv = ref 0. in
      if how land 0x01 <> 0 then rv := fmax !rv ((2. *. y) -. 1.);
      if how land 0x02 <> 0 then rv := fmax !rv ((2. *. x) -. 1.);
      if how land 0x04 <> 0 then rv := fmax !rv (1. -. (2. *. y));
      if how land 0x08 <> 0 then rv := fmax !rv (1. -. (2. *. x));
      (match interior with
      | 2 ->
          let round v1 v2 = 1.0 -. sqrt ((v1 *. v1) +. (v2 *. v2)) in
          if how land 0x40 <> 0 then rv := fmax !rv (round (2. -. (2. *. x)) (2. *. y));
          if how land 0x80 <> 0 then rv := fmax !rv (round (2. *. x) (2. *. y));
          if how land 0x10 <> 0 then rv := fmax !rv (round (2. *. x) (2. -. (2. *. y)));
          if how land 0x20 <> 0 then rv := fmax !rv (round (2. -. (2. *. x)) (2. -. (2. *. y)))
      | 1 ->
          let cut v1 v2 = 1.0 -. (v1 +. v2) in
          if how land 0x40 <> 0 then rv := fmax !rv (cut (2. -. (2. *. x)) (2. *. y));
          if how land 0x80 <> 0 then rv := fmax !rv (cut (2. *. x) (2. *. y));
          if how land 0x10 <> 0 then rv := fmax !rv (cut (2. *. x) (2. -. (2. *. y)));
          if how land 0x20 <> 0 then rv := fmax !rv (cut (2. -. (2. *. x)) (2. -. (2. *. y)))
      | _ ->
          if how land 0x10 <> 0 then rv := fmax !rv (fmin (1. -. (2. *. x)) ((2. *. y) -. 1.));
          if how land 0x20 <> 0 then rv := fmax !rv (fmin ((2. *. x) -. 1.) ((2. *. y) -. 1.));
          if how land 0x40 <> 0 then rv := fmax !rv (fmin ((2. *. x) -. 1.) (1. -. (2. *. y)));
          if how land 0x80 <> 0 then rv := fmax !rv (fmin (1. -. (2. *. x)) (1. -. (2. *. y))));
      (match exterior with
      | 2 ->
          let v1 = (2. *. x) -. 1. and v2 = (2. *. y) -. 1. in
          if
            (how land 0x06 = 0x06 && v1 >= 0.0 && v2 <= 0.0)
            || (how land 0x0C = 0x0C && v1 <= 0.0 && v2 <= 0.0)
            || (how land 0x09 = 0x09 && v1 <= 0.0 && v2 >= 0.0)
            || (how land 0x03 = 0x03 && v1 >= 0.0 && v2 >= 0.0)
          then rv := fmax !rv (fmin (sqrt ((v1 *. v1) +. (v2 *. v2))) 1.0)
      | 1 ->
          let cut v1 v2 = fmin (2.0 -. (v1 +. v2)) 1.0 in
          if how land 0x06 = 0x06 then rv := fmax !rv (cut (2. -. (2. *. x)) (2. *. y));
          if how land 0x0C = 0x0C then rv := fmax !rv (cut (2. *. x) (2. *. y));
          if how land 0x09 = 0x09 then rv := fmax !rv (cut (2. *. x) (2. -. (2. *. y)));
          if how land 0x03 = 0x03 then rv := fmax !rv (cut (2. -. (2. *. x)) (2. -. (2. *. y)))
      | _ -> ());
      !rv
    end

  (* Triangles and hexagons. The point goes into an equilateral triangle of side 1 with its base
     on z = 0 (its column xv and row zv counted in half-triangles), whose edges and corners are
       1: the left edge, 2: the right edge, 4: the base;
     the bits 0x10…0x400 mark corners whose tile is rounded (form), and 0x1000…0x4000 (hexagons)
     the vertices where a tile's interior corner is *)
  (* the edges and corners of the triangle in column [xv] and row [zv] of a 3-sided pavement *)
  let trigonal_how tile number xv zv =
    match tile with
    | 6 ->
        let xv, zv, lng =
          match number - 1 with
          | 0 | 1 | 9 -> (pmod (xv + (5 * zv)) 6, 0, 0)
          | 2 | 10 | 11 -> (pmod (xv + (3 * (zv land 1))) 6, zv land 1, 0)
          | 3 -> (pmod (xv + (14 * (pmod zv 6 / 2))) 6, zv land 1, 6)
          | 4 | 8 -> (pmod (xv + (8 * (pmod zv 6 / 2))) 6, zv land 1, 6)
          | 5 -> (pmod xv 6, zv land 1, 6)
          | 6 | 7 -> ((xv - (pmod zv 12 / 3)) land 3, pmod zv 3, 4)
          | _ -> (xv, zv, 0)
        in
        entry trihexagon number (xv + (zv * lng))
    | 5 ->
        let xv =
          match number - 1 with
          | 0 | 1 | 2 -> pmod (xv + (5 * (zv land 1))) 10
          | 3 -> pmod (xv + (3 * pmod zv 10)) 10
          | _ -> xv
        in
        entry tripentagon number xv
    | 4 ->
        let zv = zv land 3 in
        entry tritetragon number (((xv + zv) land 3) + ((zv land 1) * 4))
    | 3 -> entry tritrigon number (pmod (xv + (3 * (zv land 1))) 6)
    | 2 -> 0x166
    | _ -> 0x07

  (* the cell of 60 triangles (or fewer) of a 6-sided pavement: [rows] rows of 6 columns, the
     rows shifted by [shift] per 6 of [period] columns *)
  let[@inline] sixty period shift rows xv zv = pmod xv 6 + (6 * pmod (zv + (shift * (pmod xv period / 6))) rows)

  (* the edges and corners of the triangle in column [xv] and row [zv] of a 6-sided pavement *)
  let hexagonal_how tile number xv zv =
    match tile with
    | 5 ->
        let i =
          match number - 1 with
          | 0 | 2 | 3 | 5 | 6 | 19 -> sixty 6 0 10 xv zv
          | 1 | 4 | 9 -> sixty 30 (-2) 10 xv zv
          | 7 -> pmod xv 3 + (3 * pmod (zv - (7 * (pmod xv 60 / 3))) 20)
          | 8 | 10 | 13 | 14 | 15 | 17 | 20 | 21 -> sixty 30 2 10 xv zv
          | 11 | 16 -> sixty 30 (-6) 10 xv zv
          | 12 | 18 -> sixty 30 6 10 xv zv
          | _ -> xv
        in
        entry hexpentagon number i
    | 4 ->
        let i =
          match number - 1 with
          | 0 -> pmod xv 6 + (6 * (zv land 0x07))
          | 3 | 4 | 5 -> sixty 24 (-2) 8 xv zv
          | 2 -> pmod xv 12 + (12 * (zv land 0x01))
          | 1 -> sixty 12 2 8 xv zv
          | 6 -> pmod xv 12 + (12 * pmod zv 4)
          | _ -> xv
        in
        entry hextetragon number i
    | 3 ->
        let i =
          match number - 1 with
          | 0 -> sixty 6 0 6 xv zv
          | 1 -> sixty 18 2 6 xv zv
          | 2 -> pmod xv 18 + (18 * (zv land 0x01))
          | _ -> xv
        in
        entry hextrigon number i
    | 2 -> entry hexdigon number (pmod xv 6 + (6 * (zv land 1)))
    | _ -> entry hexmonogon number (pmod (xv + (3 * (zv land 1))) 6)

  (* Triangles and hexagons. The point goes into an equilateral triangle of side 1 with its base
     on z = 0 (its column xv and row zv counted in half-triangles), whose edges and corners are
       1: the left edge, 2: the right edge, 4: the base;
     the bits 0x10…0x400 mark corners whose tile is rounded (form), and 0x1000…0x4000 (hexagons)
     the vertices where a tile's interior corner is. [how_of] gives the triangle's edges and
     corners from its column and row. *)
  let triangles how_of tile number form interior exterior (p : Vec.t) =
    let xv = int_of_float (floor p.x) and zv = int_of_float (floor (p.z /. sqrt3)) in
    let x = ref (p.x -. float_of_int xv) and z = ref (p.z -. (sqrt3 *. float_of_int zv)) in
    let xv = ref (xv * 2) and zv = ref (zv * 2) in
    if !z > sqrt3_2 then begin
      z := !z -. sqrt3_2;
      if !x > 0.5 then begin
        x := !x -. 0.5;
        incr xv
      end
      else begin
        x := !x +. 0.5;
        decr xv
      end;
      incr zv
    end;
    if !x = 0.0 || !z /. !x > sqrt3 then begin
      z := sqrt3_2 -. !z;
      x := 0.5 -. !x;
      decr xv
    end;
    if !x = 1.0 || !z /. (1.0 -. !x) > sqrt3 then begin
      z := sqrt3_2 -. !z;
      x := 1.5 -. !x;
      incr xv
    end;
    let how = how_of tile number !xv !zv and x = !x and z = !z in
    (* the value in the triangle at (x, z) whose edges and corners are [how] *)
    let rv = ref 0. in
    if how land 0x01 <> 0 then rv := fmax !rv (1.0 -. (Float.abs ((sqrt3 *. x) -. z) *. sqrt3));
    if how land 0x02 <> 0 then rv := fmax !rv (1.0 -. (Float.abs ((sqrt3 *. (1.0 -. x)) -. z) *. sqrt3));
    if how land 0x04 <> 0 then rv := fmax !rv (1.0 -. (z *. 2.0 *. sqrt3));
    (* the corners that are inside a tile: at the apex (0x83 clear or bit 0x4000), the left
       (0x85, 0x2000) and the right (0x86, 0x1000) *)
    let apex = how land 0x83 = 0x00 || how land 0x4000 = 0x4000
    and left = how land 0x85 = 0x00 || how land 0x2000 = 0x2000
    and right = how land 0x86 = 0x00 || how land 0x1000 = 0x1000 in
    (match interior with
    | 1 ->
        let dist1 = 1.0 -. Float.abs ((sqrt3 *. z) +. x)
        and dist2 = 1.0 -. Float.abs ((sqrt3 *. z) -. x +. 1.0)
        and dist3 = 1.0 -. (x *. 2.0) in
        if apex && dist1 < 0. && dist2 < 0. then
          rv :=
            fmax !rv
              (fmin
                 ((3.0 /. 2.0 *. Float.abs ((sqrt3 *. z) +. x)) -. 2.0)
                 ((3.0 /. 2.0 *. Float.abs ((sqrt3 *. z) -. x +. 1.0)) -. 2.0));
        if left && dist1 > 0. && dist3 > 0. then
          rv := fmax !rv (fmin (1.0 -. (3.0 /. 2.0 *. Float.abs ((sqrt3 *. z) +. x))) (1.0 -. (x *. 3.0)));
        if right && dist3 < 0. && dist2 > 0. then
          rv := fmax !rv (fmin (1.0 -. (3.0 /. 2.0 *. Float.abs ((sqrt3 *. z) -. x +. 1.0))) ((x *. 3.0) -. 2.0))
    | 2 ->
        let round d1 d2 = 1.0 -. (sqrt ((d1 *. d1) +. (d2 *. d2)) *. 3.0) in
        if apex then rv := fmax !rv (round (x -. 0.5) (z -. sqrt3_2));
        if left then rv := fmax !rv (round x z);
        if right then rv := fmax !rv (round (x -. 1.0) z)
    | 0 ->
        if apex then rv := fmax !rv (1.0 -. ((sqrt3_2 -. z) *. 2.0 *. sqrt3));
        if left then rv := fmax !rv (1.0 -. (Float.abs ((sqrt3 *. x) +. z) *. sqrt3));
        if right then rv := fmax !rv (1.0 -. (Float.abs ((sqrt3 *. (x -. 1.0)) -. z) *. sqrt3))
    | _ -> ());
    (match exterior with
    | 2 ->
        let dist1 = 1.0 -. Float.abs ((sqrt3 *. z) +. x)
        and dist2 = 1.0 -. Float.abs ((sqrt3 *. z) -. x +. 1.0)
        and dist3 = 1.0 -. (x *. 2.0) in
        if
          (how land 0x03 = 0x03 && dist1 <= 0.0 && dist2 <= 0.0)
          || (how land 0x06 = 0x06 && dist2 >= 0.0 && dist3 <= 0.0)
          || (how land 0x05 = 0x05 && dist1 >= 0.0 && dist3 >= 0.0)
        then
          let v1 = x -. 0.5 and v2 = z -. (sqrt3_2 /. 3.0) in
          rv := fmin 1.0 (2. *. sqrt3 *. sqrt ((v1 *. v1) +. (v2 *. v2)))
    | 1 ->
        let dist1 = 1.0 -. (Float.abs ((sqrt3 *. x) -. z) *. sqrt3)
        and dist2 = 1.0 -. (Float.abs ((sqrt3 *. (1.0 -. x)) -. z) *. sqrt3)
        and dist3 = 1.0 -. (z *. 2.0 *. sqrt3) in
        let v1 = x -. 0.5 and v2 = z -. (sqrt3_2 /. 3.0) in
        if how land 0x03 = 0x03 && dist1 >= 0.0 && dist2 >= 0.0 then rv := fmin 1.0 (Float.abs (v2 *. 2.0 *. sqrt3));
        if how land 0x06 = 0x06 && dist2 >= 0.0 && dist3 >= 0.0 then
          rv := fmin 1.0 (Float.abs ((sqrt3 *. v1) -. v2) *. sqrt3);
        if how land 0x05 = 0x05 && dist1 >= 0.0 && dist3 >= 0.0 then
          rv := fmin 1.0 (Float.abs ((sqrt3 *. v1) +. v2) *. sqrt3)
    | _ -> ());
    let dist1 = 1.0 -. Float.abs ((sqrt3 *. z) +. x)
    and dist2 = 1.0 -. Float.abs ((sqrt3 *. z) -. x +. 1.0)
    and dist3 = 1.0 -. (x *. 2.0) in
    (* a rounded (2) or cut (1) corner of a tile returns at once *)
    match form with
    | 2 ->
        let arc v1 v2 = fmin (fmax (2.0 *. sqrt3 *. (sqrt ((v1 *. v1) +. (v2 *. v2)) -. (sqrt3 /. 3.0))) 0.0) 1.0 in
        if how land 0x120 = 0x120 && dist1 < 0. && dist2 < 0. then arc x z
        else if how land 0x140 = 0x140 && dist1 > 0. && dist3 > 0. then arc (x -. 0.5) (z -. sqrt3_2)
        else if how land 0x210 = 0x210 && dist1 < 0. && dist2 < 0. then arc (x -. 1.0) z
        else if how land 0x240 = 0x240 && dist3 < 0. && dist2 > 0. then arc (x -. 0.5) (z -. sqrt3_2)
        else if how land 0x410 = 0x410 && dist1 > 0. && dist3 > 0. then arc (x -. 1.0) z
        else if how land 0x420 = 0x420 && dist3 < 0. && dist2 > 0. then arc x z
        else !rv
    | 1 ->
        if how land 0x120 = 0x120 && dist1 < 0. && dist2 < 0. then fmin (-.dist1 *. 2.) 1.0
        else if how land 0x140 = 0x140 && dist1 > 0. && dist3 > 0. then fmin (dist1 *. 2.) 1.0
        else if how land 0x210 = 0x210 && dist1 < 0. && dist2 < 0. then fmin (-.dist2 *. 2.) 1.0
        else if how land 0x240 = 0x240 && dist3 < 0. && dist2 > 0. then fmin (dist2 *. 2.) 1.0
        else if how land 0x410 = 0x410 && dist1 > 0. && dist3 > 0. then fmin (dist3 *. 2.) 1.0
        else if how land 0x420 = 0x420 && dist2 > 0. && dist3 < 0. then fmin (-.dist3 *. 2.) 1.0
        else !rv
    | _ -> !rv

  let value side tile number form interior exterior p =
    match side with
    | 6 -> triangles hexagonal_how tile number form interior 0 p (* hexagons have no exterior *)
    | 4 -> tetragonal tile number form interior exterior p
    | _ -> triangles trigonal_how tile number form interior exterior p
end

(* ---------------------------------------------------------------------------------------------- *)
(* Evaluate_TPat's switch *)

let value_with ~frequency ~phase (p : Scene.pattern) (warps : Scene.warp list) gen (hit : hit) (q : Vec.t) =
  match p with
  | Checker -> checker q
  | Gradient v -> gradient v q
  | Hexagon -> hexagon q
  | Brick { size; mortar } -> brick size mortar q
  | Square -> square q
  | Triangular -> triangular q
  | Cubic -> cubic q
  | Agate scale -> agate scale warps gen q
  | Bozo | Spotted | Bumps -> Noise.noise gen q
  | Granite -> granite gen q
  | Leopard -> leopard q
  | Marble -> marble warps gen q
  | Wood -> wood warps q
  | Onion -> onion q
  | Radial -> radial q
  | Cells -> cells q
  | Crackle { form; metric; offset; solid } -> crackle form metric offset solid gen q
  | Wrinkles -> wrinkles gen q
  | Dents -> dents gen q
  | Waves n -> waves n (Precision.f32 frequency) (Precision.f32 phase) q
  | Ripples n -> ripples n (Precision.f32 frequency) (Precision.f32 phase) q
  | Quilted { control0; control1 } -> quilted control0 control1 q
  | Facets _ -> invalid_arg "Patterns.value: facets is a normal pattern only and has no value"
  | Spiral1 arms -> spiral1 arms warps gen q
  | Spiral2 arms -> spiral2 arms warps gen q
  | Planar -> planar q
  | Boxed -> boxed q
  | Spherical -> spherical q
  | Cylindrical -> cylindrical q
  | Fractal f -> fractal f q
  | Pavement { side; tile; number; exterior; interior; form } ->
      Pavement.value side tile number form interior exterior q
  | Tiling n -> Tiling.value n q
  | Aoi -> aoi hit
  | Slope s -> slope s hit q
  | Average -> invalid_arg "Patterns.value: average has no value (it averages the entries of its map)"
  | Object_pattern t -> object_pattern t q

let value p warps gen hit q = value_with ~frequency:1. ~phase:0. p warps gen hit q
