(* The value of every pattern (pattern.cpp's Evaluate_TPat, before frequency, phase and wave);
   §17.4–§17.7 for checker, gradient, hexagon and brick. Every formula keeps POV-Ray's order of
   floating-point operations, its constants as written and its C conversions, so that a value here
   is the double POV-Ray computes. *)

type hit = { normal : Vec.t; dir : Vec.t; uv : Vec.t }

let no_hit = { normal = Vec.make 0. 1. 0.; dir = Vec.make 0. 0. 1.; uv = Vec.zero }

(* No surface: [no_hit], or a hit made from it to carry UV coordinates alone (a shadow ray's
   crossing), which shares its normal *)
let no_surface hit = hit.normal == no_hit.normal

(* ---------------------------------------------------------------------------------------------- *)
(* C's arithmetic *)

open C_float

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
let default_turb = Warp.default_turb

(* ---------------------------------------------------------------------------------------------- *)
(* §17.4–§17.7 *)

(* §17.4: a coordinate that is an integer, or within 1e-10 below one, belongs to the cell above *)
let checker (q : Vec.t) =
  let s = Precision.(floor (q.x +. epsilon) +. floor (q.y +. epsilon) +. floor (q.z +. epsilon)) in
  if c_int s land 1 = 1 then 1. else 0.

(* pattern.cpp object_pattern: 1 inside the object (Inside_Object: inside every clip object, then
   the object's own Inside test), else 0 *)
let object_pattern (t : Scene.object_test) (q : Vec.t) = if t.inside q then 1. else 0.

(* pattern.cpp function_pattern: the function at the point, taken modulo 1 above 1 *)
let function_pattern f (q : Vec.t) =
  let v = Fn.at_point f q.x q.y q.z in
  if v > 1. then Float.rem v 1. else v

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
  if no_surface hit then 0.0
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
  if no_surface hit then 0.0
  else
    let c = Vec.dot (Vec.normalize hit.normal) (Vec.normalize hit.dir) in
    let c = if c < -1.0 then -1.0 else if c > 1.0 then 1.0 else c in
    acos c /. Float.pi

(* ---------------------------------------------------------------------------------------------- *)
(* tiling and pavement: modules of their own (Tiling, Pavement) *)

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
  | Pigment_pattern pp -> pp.grey q
  | No_pattern -> 0.
  | Bitmap _ -> invalid_arg "Patterns.value: an image_map or bump_map has a colour or a normal, not a value"
  | Image_pattern b -> Image_map.value b q
  | Function_pattern f -> function_pattern f q

let value p warps gen hit q = value_with ~frequency:1. ~phase:0. p warps gen hit q
